#!/usr/bin/python3
"""The plot of docs/precision.md: error rate against word width, one line per scene and depth.

For each width the best fraction split counts (the format an architect would choose at that
width). Error = wrong hit/miss plus hits on another voxel than float64's, per ray.
    scripts/precision_plot.py DIRECTORY   (reads DIRECTORY/*.csv of `rtusim precision`)
"""
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def best_by_width(path):
    best = {}
    with open(path, newline="") as file:
        for row in csv.DictReader(file):
            width = int(row["total_bits"])
            error = float(row["wrong_hit_miss_rate"]) + float(row["different_voxel_rate"])
            best[width] = min(best.get(width, 1.0), error)
    return sorted(best.items())


def main(directory):
    floor = 1e-6  # zero errors are drawn here, below one ray in a million
    figure, axes = plt.subplots(figsize=(8, 5))
    for path in sorted(glob.glob(os.path.join(directory, "*.csv"))):
        name = os.path.splitext(os.path.basename(path))[0]
        points = best_by_width(path)
        widths = [w for w, _ in points]
        errors = [max(e, floor) for _, e in points]
        axes.plot(widths, errors, marker="o", label=name.replace("_", ", depth "))
    axes.set_yscale("log")
    axes.set_ylim(floor / 2, 1)
    axes.axhline(1e-3, color="grey", linestyle=":", linewidth=1)
    axes.set_xlabel("word width (bits), best fraction split")
    axes.set_ylabel("rays wrong (hit/miss or other voxel)")
    axes.set_title("Fixed point against float64, 256x256 frame, default camera")
    axes.set_xticks([16, 20, 24, 28, 32, 40, 48])
    axes.grid(True, which="major", alpha=0.3)
    axes.legend(fontsize=8, ncol=2)
    figure.tight_layout()
    out = os.path.join(directory, "precision_by_width.png")
    figure.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out/precision")
