#!/usr/bin/env python3
"""The table and plots of issue 30's study (bench/comparison_study.sh, docs/comparison.md "The
study") from `rtusim compare --json` files OUT/SCENE-common.json and OUT/SCENE-seed.json: prints the
markdown table and writes IMAGES/study_fps.png (frame rate per architecture and scene),
IMAGES/study_bytes.png (bytes per ray the cores fetch and from DRAM) and
IMAGES/study_pareto_dsp48e.png, study_pareto_bram18k.png (frame rate against the resource
estimate, each scene's Pareto front).
Usage: bench/comparison_study.py OUT IMAGES"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SCENES = [("bunny00", "bunny"), ("armadillo", "armadillo"), ("ChineseDragon-10kv", "dragon"),
          ("refined_elephant", "elephant"), ("room", "room"),
          ("default", "scenes/default.toml")]
ARCHITECTURES = ["svo", "bvh", "bih", "kd", "raypipe"]
COLOURS = {"svo": "tab:green", "bvh": "tab:blue", "bih": "tab:red", "kd": "tab:orange",
           "raypipe": "tab:purple"}


def value(row, key):
    for part in (row, row.get("figures", {}), row.get("agreement", {})):
        if key in part:
            return part[key]
    return None


def load(folder):
    """{scene: {"heading": ..., "rows": [(label, part, row)]}}: the common rows, then the seeds';
    a BIH row run smaller (the sets common-bih and seed-bih) is labelled with its size, and left
    out of the plots, whose frame rates are all at the study's size."""
    scenes = {}
    for scene, _ in SCENES:
        for part in ("common", "common-bih", "seed", "seed-bih"):
            path = os.path.join(folder, "%s-%s.json" % (scene, part))
            if not os.path.exists(path):
                continue
            with open(path) as source:
                compared = json.load(source)
            entry = scenes.setdefault(scene, {"heading": compared, "rows": []})
            size = " at %dx%d" % (compared["width"], compared["height"]) if part.endswith(
                "-bih") else ""
            for row in compared["rows"]:
                if row["status"] != "ok":
                    continue
                label = row["architecture"] if part.startswith("common") else "%s (%s)" % (
                    row["architecture"], row.get("preset") or "default")
                entry["rows"].append((label + size, part, row))
    return scenes


def number(v, digits=2):
    if v is None:
        return "-"
    if isinstance(v, str):
        return v
    if isinstance(v, int) or abs(v) >= 1000:
        return "{:,.0f}".format(v)
    if v != 0 and abs(v) < 0.01:
        return "%.1e" % v
    return "{:,.{d}f}".format(v, d=digits)


def table(scenes):
    columns = [("fps", "frames/s"), ("cycles_per_ray", "cycles/ray"),
               ("core_bytes_per_ray", "B/ray core"), ("dram_bytes_per_ray", "B/ray DRAM"),
               ("l1_hit_rate", "L1 hit"), ("nodes_per_ray", "nodes/ray"),
               ("tests_per_ray", "tests/ray"), ("utilisation", "util"), ("limit", "limit"),
               ("bram18k", "BRAM18k"), ("dsp48e", "DSP48E"), ("hit_miss_differ", "hit/miss"),
               ("other_object", "other obj"), ("mean_depth_error", "depth err")]
    lines = ["| scene | architecture | image MB | " + " | ".join(h for _, h in columns) + " |",
             "|---" * (len(columns) + 3) + "|"]
    for scene, name in SCENES:
        if scene not in scenes:
            continue
        heading = scenes[scene]["heading"]
        first = "%s (%s, SVO depth %d)" % (name, heading["scene"].split(", ")[-1],
                                           heading["depth"])
        for label, _, row in scenes[scene]["rows"]:
            cells = [number(value(row, key), 5 if key == "mean_depth_error" else 2)
                     for key, _ in columns]
            lines.append("| %s | %s | %.2f | %s |" % (first, label, row["image_bytes"] / 1e6,
                                                      " | ".join(cells)))
            first = ""
    return "\n".join(lines)


def grouped_bars(ax, scenes, key, title, log):
    names = [s for s, _ in SCENES if s in scenes]
    width = 0.8 / len(ARCHITECTURES)
    for k, architecture in enumerate(ARCHITECTURES):
        values = []
        for scene in names:
            rows = [r for label, part, r in scenes[scene]["rows"]
                    if part == "common" and r["architecture"] == architecture]
            values.append(value(rows[0], key) if rows else None)
        positions = [i + (k - (len(ARCHITECTURES) - 1) / 2) * width for i in range(len(names))]
        ax.bar(positions, [v or 0 for v in values], width, label=architecture,
               color=COLOURS[architecture])
        for x, v in zip(positions, values):
            if v is None:  # the ray pipe's caches count no bytes
                ax.text(x, 0.03, "n/a", rotation=90, fontsize=7, ha="center", va="bottom",
                        transform=ax.get_xaxis_transform())
    ax.set_xticks(range(len(names)))
    # A path breaks after its folder, so it does not run into its neighbour's label.
    ax.set_xticklabels([dict(SCENES)[s].replace("/", "/\n") for s in names], fontsize=8)
    ax.set_title(title, fontsize=10)
    if log:
        ax.set_yscale("log")
    ax.grid(axis="y", alpha=0.3)


def pareto(ax, points):
    """Points (resource, fps, label): the front no other point beats with no more of the resource
    and no lower frame rate, drawn as a staircase."""
    front, best = [], -1
    for x, y, label in sorted(points, key=lambda p: (p[0], -p[1])):
        if y > best:
            front.append((x, y))
            best = y
    xs, ys = [], []
    for x, y in front:
        if xs:
            xs.append(x)
            ys.append(ys[-1])
        xs.append(x)
        ys.append(y)
    xs.append(max(p[0] for p in points))  # the last step runs on to the right
    ys.append(ys[-1])
    ax.plot(xs, ys, color="grey", lw=1.5, zorder=1)
    ax.scatter([x for x, _ in front], [y for _, y in front], s=120, facecolors="none",
               edgecolors="grey", zorder=1)


def pareto_plot(scenes, resource, title, path):
    names = [s for s, _ in SCENES if s in scenes]
    columns = 3
    rows_ = (len(names) + columns - 1) // columns
    fig, axes = plt.subplots(rows_, columns, figsize=(12, 3.6 * rows_), squeeze=False)
    for ax in axes.flat[len(names):]:
        ax.axis("off")
    for ax, scene in zip(axes.flat, names):
        points = []
        for label, part, row in scenes[scene]["rows"]:
            x, y = value(row, resource), value(row, "fps")
            if x is None or y is None or part.endswith("-bih"):
                continue
            points.append((x, y, label))
            ax.scatter([x], [y], color=COLOURS[row["architecture"]],
                       marker="o" if part == "common" else "s", zorder=2)
            ax.annotate(label, (x, y), fontsize=7, xytext=(3, 3), textcoords="offset points")
        pareto(ax, points)
        ax.set_xscale("symlog", linthresh=10)
        ax.set_yscale("log")
        ax.set_title(dict(SCENES)[scene], fontsize=10)
        ax.set_xlabel(resource)
        ax.set_ylabel("frames/s")
        ax.grid(alpha=0.3)
    fig.suptitle(title + " (circles: common configuration, squares: the seed's; grey: the "
                 "Pareto front, its points ringed)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main():
    folder, images = sys.argv[1], sys.argv[2]
    scenes = load(folder)
    print(table(scenes))
    fig, ax = plt.subplots(figsize=(10, 3.8))
    grouped_bars(ax, scenes, "fps", "Frame rate (frames/s), common configuration", True)
    ax.legend(fontsize=8, ncol=5, loc="upper center", bbox_to_anchor=(0.5, -0.12))
    fig.tight_layout()
    fig.savefig(os.path.join(images, "study_fps.png"), dpi=90)
    plt.close(fig)
    fig, axes = plt.subplots(1, 2, figsize=(12, 3.8))
    grouped_bars(axes[0], scenes, "core_bytes_per_ray", "Bytes per ray the cores fetch", True)
    grouped_bars(axes[1], scenes, "dram_bytes_per_ray", "Bytes per ray from DRAM", True)
    axes[0].legend(fontsize=8, ncol=5, loc="upper center", bbox_to_anchor=(1.1, -0.12))
    fig.tight_layout()
    fig.savefig(os.path.join(images, "study_bytes.png"), dpi=90)
    plt.close(fig)
    pareto_plot(scenes, "dsp48e", "Frame rate against DSP48E slices",
                os.path.join(images, "study_pareto_dsp48e.png"))
    pareto_plot(scenes, "bram18k", "Frame rate against 18 Kbit block RAMs",
                os.path.join(images, "study_pareto_bram18k.png"))


if __name__ == "__main__":
    main()
