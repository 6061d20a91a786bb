"""The HTML report of rtusim rows: the best configuration by the objective, the comparison of
several inputs, the plots, the rows in a sortable table with the best row of each group marked,
the failed rows and the configuration."""

import base64
import datetime
import html
import json
import os

import matplotlib.pyplot as plt

from rtusim_diff import paired_rows
from rtusim_figures import make_plots, render
from rtusim_objective import format_gain, objective_text, summaries
from rtusim_rows import (InputError, cycles_per_ray_of, fps_of, describe, fixed_config,
                         format_value, hit_rate_of, input_keys, sort_key, varied_keys)


def cell(value, sort=None):
    """A table cell; numbers right-aligned and sorted by value (data-sort)."""
    key = "" if sort is None else ' data-sort="%s"' % html.escape(str(sort))
    if value is None or value == "":
        return "<td%s></td>" % key
    if isinstance(value, bool):
        return "<td>%s</td>" % str(value).lower()
    if isinstance(value, (int, float)):
        # four digits: a frame rate's or hit rate's per cent shows
        text = "{:,}".format(value) if isinstance(value, int) else \
            "%.4g" % value if abs(value) < 1e4 else "{:,.0f}".format(value)
        return '<td class="num" data-sort="%r">%s</td>' % (value, text)
    return "<td%s>%s</td>" % (key, html.escape(str(value)))


STYLE = """
body { font-family: system-ui, -apple-system, "Segoe UI", sans-serif; margin: 2em auto;
       max-width: 1250px; padding: 0 1em; color: #222; }
h1 { font-size: 1.6em; } h2 { font-size: 1.25em; margin-top: 1.8em; border-bottom: 1px solid #ddd; }
table { border-collapse: collapse; font-size: 0.9em; margin: 0.5em 0; }
th, td { border: 1px solid #ddd; padding: 3px 8px; text-align: left; vertical-align: top;
         white-space: nowrap; }
th { background: #f3f3f3; } td.num { text-align: right; font-variant-numeric: tabular-nums; }
table.sortable th { cursor: pointer; } table.sortable th:hover { background: #e6e6e6; }
tr.failed td { background: #fff0f0; } tr.best td { background: #e7f5e7; font-weight: 600; }
.error { color: #b00020; white-space: normal; }
figure { margin: 1em 0; } figure img { width: 100%; height: auto; border: 1px solid #eee; }
figcaption { font-size: 0.85em; color: #555; }
.scroll { overflow-x: auto; } code { background: #f5f5f5; padding: 0 3px; }
"""

# Sorts a table.sortable by the column clicked (again: the other way), by data-sort when given.
SCRIPT = """
document.querySelectorAll("table.sortable th").forEach(function (th) {
  th.addEventListener("click", function () {
    var column = th.cellIndex;
    var body = th.closest("table").tBodies[0], rows = Array.from(body.rows);
    var up = th.dataset.order !== "up"; th.dataset.order = up ? "up" : "down";
    function key(row) { var c = row.cells[column]; return c.dataset.sort !== undefined ?
      c.dataset.sort : c.textContent; }
    rows.sort(function (a, b) { var x = key(a), y = key(b), nx = parseFloat(x), ny = parseFloat(y);
      var order = (!isNaN(nx) && !isNaN(ny)) ? nx - ny : x.localeCompare(y);
      return up ? order : -order; });
    rows.forEach(function (row) { body.appendChild(row); });
  });
});
"""


def best_section(rows, objectives, groups, base):
    """The best configuration per group, and the set of best rows' numbers (to mark them)."""
    out = ["<h2>Best configuration</h2>"]
    found = summaries(rows, objectives, groups, base)
    objective = objectives[0]
    keys = list(found[0]["base_values"])
    out.append("<p>Objective %s; the gain is the rate's rise over the base configuration (%s%s)."
               "</p>" % (html.escape(objective.describe()),
                         html.escape(describe(found[0]["base_values"], keys) or "the only one"),
                         "" if base else ": the first row's values, or <code>--base "
                         "KEY=VALUE</code>"))
    out.append('<table id="best"><thead><tr><th>group</th><th>best row</th><th>%s</th>'
               "<th>base row</th><th>base %s</th><th>gain</th></tr></thead><tbody>"
               % (html.escape(objective.name), html.escape(objective.name)))
    for summary in found:
        best, base_row = summary["best"], summary["base"]
        ties = "".join(", #%d" % r["index"] for r in summary["ties"])
        out.append("<tr><td>%s</td><td>#%d %s%s</td>%s<td>%s</td>%s<td>%s</td></tr>" % (
            html.escape(describe(summary["group"], list(summary["group"])) or "all rows"),
            best["index"], html.escape(describe(best["config"], keys)),
            " (as good: %s)" % ties[2:] if ties else "",
            cell(objective_text(objective.value(best))),
            "#%d" % base_row["index"] if base_row else "none has the base configuration",
            cell(objective_text(objective.value(base_row)) if base_row else None),
            format_gain(summary["gain"])))
    out.append("</tbody></table>")
    for summary in found:
        if summary["front"]:
            out.append("<p>Pareto front of %s, %s: %s</p>" % (
                " and ".join(html.escape(o.describe()) for o in objectives),
                html.escape(describe(summary["group"], list(summary["group"])) or "all rows"),
                ", ".join("#%d" % r["index"] for r in summary["front"])))
    marked = {s["best"]["index"] for s in found} | {r["index"] for s in found for r in s["ties"]}
    return out, marked


def comparison_section(rows, objective):
    """Several inputs: what differs between them, then the objective of each pair of rows."""
    names = list(dict.fromkeys(r["input"] for r in rows))
    if len(names) < 2:
        return []
    out = ["<h2>Comparison of the inputs</h2>", "<table><thead><tr><th>key</th>%s</tr></thead>"
           % "".join("<th>%s</th>" % html.escape(n) for n in names)]
    first = {n: next(r for r in rows if r["input"] == n) for n in names}
    for key in input_keys(rows):
        out.append("<tr><td>%s</td>%s</tr>" % (html.escape(key), "".join(
            cell(format_value(key, first[n]["config"].get(key))) for n in names)))
    out.append("</table>")
    if len(names) != 2:
        return out
    differing, pairs = paired_rows(rows)
    varied = [k for k in varied_keys(rows) if k != "input"]
    out.append('<table class="sortable"><thead><tr>%s<th>%s %s</th><th>%s %s</th>'
               "<th>ratio</th></tr></thead><tbody>" % (
                   "".join("<th>%s</th>" % html.escape(k) for k in varied),
                   html.escape(objective.name), html.escape(names[0]),
                   html.escape(objective.name), html.escape(names[1])))
    for a, b in pairs:
        va = objective.value(a) if a and a["status"] == "ok" else None
        vb = objective.value(b) if b and b["status"] == "ok" else None
        out.append("<tr>%s%s%s%s</tr>" % (
            "".join(cell(format_value(k, (a or b)["config"].get(k))) for k in varied),
            cell(objective_text(va) if va is not None else None, va),
            cell(objective_text(vb) if vb is not None else None, vb),
            cell(vb / va if va and vb is not None else None)))
    out.append("</tbody></table>")
    return out


def rows_section(rows, varied, marked):
    columns = ["rays", "total_cycles", "cycles_per_ray", "fps", "frame_ms", "L1 hit rate",
               "L2 hit rate", "limit"]
    out = ["<h2>Rows</h2>", "<p>Click a heading to sort; the best row of each group is marked "
           "&#9733;.</p>",
           '<div class="scroll"><table id="rows" class="sortable"><thead><tr><th>#</th>%s'
           "<th>preset</th><th>clock</th>%s<th>status</th></tr></thead><tbody>" % (
               "".join("<th>%s</th>" % html.escape(k) for k in varied),
               "".join("<th>%s</th>" % c for c in columns))]
    for row in rows:
        stats = row["statistics"] or {}
        ok = bool(row["statistics"])
        values = [stats.get("rays"), stats.get("total_cycles"),
                  cycles_per_ray_of(row) if ok else None, fps_of(row) if ok else None,
                  stats.get("frame_ms"),
                  hit_rate_of(row, "l1") if ok else None, hit_rate_of(row, "l2") if ok else None,
                  stats.get("limit")]
        status = html.escape(row["status"]) + (
            ': <span class="error">%s</span>' % html.escape(row["error"]) if row["error"] else "")
        best = row["index"] in marked
        out.append('<tr%s><td class="num" data-sort="%d">%d%s</td>%s%s%s%s<td>%s</td></tr>' % (
            ' class="best"' if best else ' class="failed"' if row["status"] != "ok" else "",
            row["index"], row["index"], " &#9733;" if best else "",
            "".join(cell(format_value(k, row["config"].get(k)), row["config"].get(k))
                    for k in varied),
            cell(row["preset"] or None), cell(format_value("clock_mhz", row["config"].get(
                "clock_mhz")), row["config"].get("clock_mhz")),
            "".join(cell(v) for v in values), status))
    out.append("</tbody></table></div>")
    return out


def command_report(args, objectives, rows):
    figures = make_plots(rows)
    varied = varied_keys(rows) if len(rows) > 1 else []
    fixed = fixed_config(rows)
    ok = [r for r in rows if r["status"] == "ok"]
    failed = [r for r in rows if r["status"] != "ok"]
    scene = fixed.get("scene")
    title = "rtusim sweep report" + (" — scene %s" % scene if scene else "")
    out = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
           "<title>%s</title>" % html.escape(title), "<style>%s</style></head><body>" % STYLE,
           "<h1>%s</h1>" % html.escape(title),
           "<p>%d configurations (%d ok, %d failed) from %s. Generated %s.</p>"
           % (len(rows), len(ok), len(failed),
              ", ".join("<code>%s</code>" % html.escape(os.path.basename(p)) for p in args.inputs),
              datetime.datetime.now().strftime("%Y-%m-%d %H:%M"))]
    marked = set()
    if ok:
        try:
            best, marked = best_section(rows, objectives, args.group, args.base)
            out.extend(best)
        except InputError as error:
            out.append("<h2>Best configuration</h2><p>%s</p>" % html.escape(str(error)))
    out.extend(comparison_section(rows, objectives[0]))

    out.append("<h2>Plots</h2>")
    if not figures:
        out.append("<p>No plot applies: nothing varies that a plot needs.</p>")
    for name, fig in figures:
        svg = base64.b64encode(render(fig, "svg")).decode("ascii")
        caption = fig._suptitle.get_text().split("\n")[0] if fig._suptitle else name
        out.append('<figure id="%s"><img alt="%s" src="data:image/svg+xml;base64,%s">'
                   "<figcaption>%s (<code>%s</code>)</figcaption></figure>"
                   % (name, html.escape(caption), svg, html.escape(caption), name))
        plt.close(fig)

    out.extend(rows_section(rows, varied, marked))
    out.append("<h2>Failed rows</h2>")
    if failed:
        out.append('<div class="scroll"><table id="failed"><tr><th>configuration</th>'
                   "<th>error</th></tr>")
        for row in failed:
            out.append('<tr class="failed"><td>%s</td><td class="error">%s</td></tr>' % (
                html.escape(describe(row["config"], varied) or row["source"]),
                html.escape(row["error"] or "(no message)")))
        out.append("</table></div>")
    else:
        out.append("<p>None.</p>")

    out.append("<h2>Varied keys</h2>")
    if varied:
        out.append("<table><tr><th>key</th><th>values</th></tr>")
        for key in varied:
            values = sorted({json.dumps(r["config"].get(key)): r["config"].get(key)
                             for r in rows}.values(), key=sort_key)
            out.append("<tr><td>%s</td><td>%s</td></tr>" % (
                html.escape(key), html.escape(", ".join(format_value(key, v) for v in values))))
        out.append("</table>")
    else:
        out.append("<p>None: all rows have the same configuration.</p>")
    out.append("<h2>Fixed configuration</h2>")
    if set(fixed) <= {"width", "height", "cores"}:
        out.append("<p>An fps CSV holds width, height and cores only: report the <code>.jsonl"
                   "</code> written beside it for the whole configuration.</p>")
    presets = sorted({r["preset"] for r in rows})
    out.append('<div class="scroll"><table><tr><th>key</th><th>value</th></tr>')
    if len(presets) == 1:
        out.append("<tr><td>preset</td>%s</tr>" % cell(presets[0] or "none"))
    for key in sorted(fixed):
        out.append("<tr><td>%s</td>%s</tr>" % (html.escape(key), cell(fixed[key])))
    out.append("</table></div>")
    out.append("<script>%s</script></body></html>\n" % SCRIPT)

    directory = os.path.dirname(os.path.abspath(args.out))
    os.makedirs(directory, exist_ok=True)
    with open(args.out, "w", encoding="utf-8") as handle:
        handle.write("\n".join(out))
    print(args.out)
    return 0
