#!/usr/bin/env python3
"""Error against speed-up from `rtusim fidelity --csv` files: one point per mode and setting.

Usage: fidelity_plot.py OUT.png FILE.csv [FILE.csv ...]
Each file is one configuration (its name, without .csv, labels it). The y axis is the absolute
error of the frame's total cycles against the SystemC model; the exact modes sit on the floor.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FLOOR = 0.001  # percent: where exact modes are drawn on the log axis


def main():
    out, files = sys.argv[1], sys.argv[2:]
    figure, axes = plt.subplots(figsize=(9.5, 5), dpi=120)
    markers = {"systemc": "s", "recurrence": "D", "lt": "^", "sampled": "o"}
    colours = plt.get_cmap("tab20")
    for index, path in enumerate(files):
        label = os.path.basename(path)[: -len(".csv")]
        for row in csv.DictReader(open(path)):
            if not row["total_cycles_error"]:
                continue  # golden: untimed
            kind = row["mode"].split()[0]
            error = max(abs(float(row["total_cycles_error"])) * 100, FLOOR)
            speed = float(row["speed_up"])
            axes.scatter(speed, error, marker=markers[kind], color=colours(index % 20),
                         label=label if kind == "systemc" else None, s=36)
            if kind == "sampled":
                axes.annotate(row["mode"].split()[1], (speed, error), textcoords="offset points",
                              xytext=(4, 3), fontsize=7, color=colours(index % 20))
    axes.set_xscale("log")
    ticks = [1, 1.5, 2, 3, 4, 6, 8, 12, 16]
    axes.set_xticks(ticks)
    axes.set_xticklabels([f"{t:g}x" for t in ticks])
    axes.minorticks_off()
    axes.set_yscale("log")
    axes.axhline(3, color="grey", linestyle="--", linewidth=0.8)
    axes.text(axes.get_xlim()[0] * 1.05, 3.3, "3 %", color="grey", fontsize=8)
    axes.set_xlabel("speed-up over the SystemC model (host seconds)")
    axes.set_ylabel("|error of total cycles| (%%); exact modes at %g" % FLOOR)
    axes.set_title("Speed against accuracy: squares SystemC, diamonds recurrence, triangles "
                   "loosely-timed, circles sampled (fraction)", fontsize=9)
    axes.grid(True, which="both", linewidth=0.3)
    axes.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), title="configuration",
                title_fontsize=8)
    figure.tight_layout()
    figure.savefig(out)


if __name__ == "__main__":
    main()
