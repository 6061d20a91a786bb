"""The HTML report of `rtusim compare` (issue 30): one scene on every architecture. The table of
figures per architecture, bar plots of frame rate, cycles per ray, bytes per ray from each memory
level, work per ray and image agreement, and each architecture's difference image against the
float64 reference, all embedded (PNG as base64), so the file stands alone."""

import base64
import html
import json
import os

from rtusim_figures import render
from rtusim_report import STYLE, cell
from rtusim_rows import InputError

# (key, heading) of the table's columns, each from the row, its figures or its agreement.
COLUMNS = [("architecture", "architecture"), ("preset", "preset"), ("image_bytes", "image bytes"),
           ("build_seconds", "build s"), ("total_cycles", "frame cycles"), ("fps", "frames/s"),
           ("cycles_per_ray", "cycles/ray"), ("core_bytes_per_ray", "B/ray core"),
           ("l2_bytes_per_ray", "B/ray L2"), ("dram_bytes_per_ray", "B/ray DRAM"),
           ("l1_hit_rate", "L1 hit rate"), ("l2_hit_rate", "L2 hit rate"),
           ("nodes_per_ray", "nodes/ray"), ("tests_per_ray", "tests/ray"),
           ("utilisation", "utilisation"), ("limit", "limit"),
           ("bram18k", "18 Kbit BRAMs"), ("dsp48e", "DSP48E"),
           ("fps_per_bram18k", "frames/s per BRAM"), ("fps_per_dsp48e", "frames/s per DSP48E"),
           ("hit_miss_differ", "hit/miss differ"), ("other_object", "other object"),
           ("mean_depth_error", "mean depth error")]

# The bar plots: (title, [(key, label)], logarithmic).
PLOTS = [("Frame rate (frames/s)", [("fps", None)], True),
         ("Cycles per ray", [("cycles_per_ray", None)], False),
         ("Bytes per ray from each memory level",
          [("core_bytes_per_ray", "core fetches (L1)"), ("l2_bytes_per_ray", "L2 (L1 refills)"),
           ("dram_bytes_per_ray", "DRAM")], False),
         ("Work per ray", [("nodes_per_ray", "nodes"), ("tests_per_ray", "triangle tests")], False),
         # The resource estimate (docs/comparison.md, "Resources"): the SVO has no DSP48E.
         ("Frame rate per resource",
          [("fps_per_bram18k", "per 18 Kbit block RAM"), ("fps_per_dsp48e", "per DSP48E")], False),
         ("Pixels differing from the float64 reference",
          [("hit_miss_differ", "hit/miss"), ("other_object", "other object")], False)]


def value(row, key):
    for part in (row, row.get("figures", {}), row.get("agreement", {})):
        if key in part:
            return part[key]
    return None


def bar_plot(plt, rows, title, series, log):
    names = [r["architecture"] for r in rows]
    fig, ax = plt.subplots(figsize=(7, 3.2))
    width = 0.8 / len(series)
    for k, (key, label) in enumerate(series):
        values = [value(r, key) for r in rows]
        positions = [i + (k - (len(series) - 1) / 2) * width for i in range(len(rows))]
        bars = ax.bar(positions, [v or 0 for v in values], width, label=label)
        # An architecture without the figure (the pipe's caches, the SVO's nodes): "n/a", no bar.
        ax.bar_label(bars, labels=["n/a" if v is None else "%.3g" % v for v in values],
                     fontsize=7)
    ax.set_xticks(range(len(rows)))
    ax.set_xticklabels(names)
    ax.set_title(title)
    if log and all((value(r, series[0][0]) or 0) > 0 for r in rows):
        ax.set_yscale("log")
    if len(series) > 1:
        ax.legend(fontsize=8)
    ax.grid(axis="y", alpha=0.3)
    fig.tight_layout()
    png = base64.b64encode(render(fig, "png")).decode("ascii")
    plt.close(fig)
    return '<figure><img alt="%s" src="data:image/png;base64,%s"></figure>' % (
        html.escape(title), png)


def difference_images(rows):
    out = []
    for row in rows:
        path = row.get("difference_image")
        if not path or not os.path.exists(path):
            continue
        with open(path, "rb") as image:
            png = base64.b64encode(image.read()).decode("ascii")
        a = row["agreement"]
        out.append('<figure style="display:inline-block;width:48%%;margin:0.5%%">'
                   '<img alt="%s" src="data:image/png;base64,%s" style="image-rendering:pixelated">'
                   '<figcaption>%s: %d pixels differ in hit or miss (%d false, %d missed), %d in '
                   'object, mean depth error %.3g</figcaption></figure>'
                   % (html.escape(row["architecture"]), png, html.escape(row["architecture"]),
                      a["hit_miss_differ"], a["false_hits"], a["missed_hits"], a["other_object"],
                      a["mean_depth_error"]))
    return out


def table(rows):
    out = ['<div class="scroll"><table><tr>%s</tr>'
           % "".join("<th>%s</th>" % html.escape(h) for _, h in COLUMNS)]
    for row in rows:
        if row["status"] != "ok":
            out.append('<tr class="failed"><td>%s</td><td colspan="%d" class="error">%s</td></tr>'
                       % (html.escape(row["architecture"]), len(COLUMNS) - 1,
                          html.escape(row["error"])))
            continue
        out.append("<tr>%s</tr>" % "".join(cell(value(row, key)) for key, _ in COLUMNS))
    out.append("</table></div>")
    return out


def command_compare(args, plt):
    try:
        with open(args.inputs[0]) as source:
            compared = json.load(source)
    except (OSError, ValueError) as error:
        raise InputError("%s: %s" % (args.inputs[0], error))
    rows = compared["rows"]
    ok = [r for r in rows if r["status"] == "ok"]
    title = "rtusim compare: %s, %dx%d" % (compared["scene"], compared["width"], compared["height"])
    parts = ["<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>%s</title><style>%s"
             "</style></head><body><h1>%s</h1>" % (html.escape(title), STYLE, html.escape(title)),
             "<p>SVO depth %d. Every architecture traces the same triangles (the SVO their voxels); "
             "agreement is against the float64 watertight reference over them "
             "(docs/comparison.md).</p>" % compared["depth"], "<h2>Figures</h2>"]
    parts += table(rows)
    if ok:
        parts.append("<h2>Plots</h2>")
        parts += [bar_plot(plt, ok, title_, series, log) for title_, series, log in PLOTS]
        parts.append("<h2>Difference images</h2><p>Near black: both miss; grey: the same hit; "
                     "blue: a hit the reference does not have; red: a hit missed; yellow: "
                     "another object (triangle, or the SVO's voxel).</p>")
        parts += difference_images(ok)
    parts.append("</body></html>")
    with open(args.out, "w") as out:
        out.write("\n".join(parts) + "\n")
    return 0
