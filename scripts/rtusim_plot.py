#!/usr/bin/env python3
"""Plots and an HTML report of rtusim sweep results.

Usage:
  rtusim_plot.py plot --out-dir DIR INPUT...
  rtusim_plot.py report --out FILE.html INPUT...
  rtusim_plot.py frames --out FILE.png FRAMES.csv

INPUT is a sweep result as JSON lines (*.jsonl, one object per configuration row with
"status", "error", "config" and "statistics") or an `fps` CSV (header starting
width,height,cores,rays,total_cycles,cycles_per_ray,frame_ms,fps,limit). Rows from all inputs
are pooled. A plot is made only when the data varies what it needs:

  fps_vs_cores       frame rate against cores, one line per resolution     (cores varies)
  hit_rate_vs_l1_size / hit_rate_vs_l2_size
                     L1 and L2 hit rates against the cache size           (size varies, cached)
  core_time          busy/blocked/handover/idle: per core for one row, one bar per configuration
                     for several                                          (core times present)
  wait_histogram     scheduler waits, one series per policy/configuration (histogram present)
  cycles_per_ray_vs_dram_latency
                     cycles per ray against DRAM latency                  (latency varies)

Each plot is written as PNG and SVG. Exit status 2 with a message for missing or malformed
input, or when no plot applies (plot command).
"""

import argparse
import base64
import csv
import datetime
import html
import io
import json
import math
import os
import re
import sys
import textwrap

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import FixedLocator, FuncFormatter, NullLocator
    import numpy as np
except ImportError as error:  # pragma: no cover - depends on the host
    # A Python first on PATH (pyenv, venv) may lack Debian's python3-matplotlib: retry once with
    # the system interpreter.
    system = "/usr/bin/python3"
    if os.environ.get("RTUSIM_PLOT_REEXEC") != "1" and os.path.exists(system) \
            and os.path.realpath(sys.executable) != os.path.realpath(system):
        os.environ["RTUSIM_PLOT_REEXEC"] = "1"
        os.execv(system, [system] + sys.argv)
    sys.stderr.write("rtusim_plot: error: %s (install python3-matplotlib and python3-numpy)\n" % error)
    sys.exit(2)

PROG = "rtusim_plot"
CSV_HEADER = ["width", "height", "cores", "rays", "total_cycles", "cycles_per_ray", "frame_ms",
              "fps", "limit"]
CSV_CONFIG = ["width", "height", "cores"]
TIME_PARTS = [("busy", "busy", "#2b8a3e"), ("blocked", "blocked", "#e8590c"),
              ("handover", "waiting to hand over", "#1c7ed6"), ("idle", "idle", "#adb5bd")]
MAX_SERIES = 6      # wait histogram series
MAX_LINES = 10      # lines in a line plot
MAX_BARS = 48       # configurations in the core time plot
# Fixed keys worth naming in a plot title, in this order.
TITLE_KEYS = ["scheduler", "memory.kind", "clock_mhz", "resolution", "cores", "memory.l1.size",
              "memory.l2.size", "memory.dram.latency"]
MARKERS = ["o", "s", "^", "D", "v", "P", "X", "<", ">", "*"]

plt.rcParams.update({
    "font.size": 11,
    "axes.titlesize": 12,
    "axes.labelsize": 11,
    "legend.fontsize": 9,
    "xtick.labelsize": 10,
    "ytick.labelsize": 10,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "svg.fonttype": "path",
    "savefig.dpi": 150,
})


class InputError(Exception):
    """Missing or malformed input; reported with exit status 2."""


# ---------------------------------------------------------------------------------------------
# Reading inputs


def flatten(value, prefix=""):
    """Flattens nested config objects into dotted keys (inputs are normally flat already)."""
    flat = {}
    for key, item in value.items():
        name = prefix + str(key)
        if isinstance(item, dict):
            flat.update(flatten(item, name + "."))
        else:
            flat[name] = item
    return flat


def number(text):
    """The value of a CSV cell: int, float or the text itself."""
    text = text.strip()
    for convert in (int, float):
        try:
            return convert(text)
        except ValueError:
            pass
    return text


SIZE_UNITS = {"": 1, "B": 1, "KiB": 1024, "MiB": 1024 ** 2, "GiB": 1024 ** 3, "kB": 1000,
              "KB": 1000, "MB": 1000 ** 2, "GB": 1000 ** 3}


def config_value(value):
    """A configuration value as rtusim writes it, numbers and sizes ("4KiB") as numbers."""
    if not isinstance(value, str):
        return value
    match = re.fullmatch(r"\s*([0-9]+(?:\.[0-9]+)?)\s*([A-Za-z]*)\s*", value)
    if match and match.group(2) in SIZE_UNITS:
        amount = float(match.group(1)) * SIZE_UNITS[match.group(2)]
        return int(amount) if amount.is_integer() else amount
    return value


def read_jsonl(path, handle):
    rows = []
    for line_number, line in enumerate(handle, 1):
        if not line.strip():
            continue
        where = "%s:%d" % (path, line_number)
        try:
            obj = json.loads(line)
        except json.JSONDecodeError as error:
            raise InputError("%s: not JSON: %s" % (where, error.msg))
        if not isinstance(obj, dict):
            raise InputError("%s: expected a JSON object per line" % where)
        config = obj.get("config")
        if not isinstance(config, dict):
            raise InputError("%s: no \"config\" object" % where)
        status = obj.get("status", "ok" if "statistics" in obj else "failed")
        statistics = obj.get("statistics")
        if status == "ok" and not isinstance(statistics, dict):
            raise InputError("%s: status ok but no \"statistics\" object" % where)
        rows.append({"status": str(status), "error": str(obj.get("error") or ""),
                     "config": flatten(config),
                     "statistics": statistics if status == "ok" else None, "source": where})
    return rows


def read_csv(path, handle):
    reader = csv.reader(handle)
    header = next(reader, None)
    if header is None:
        raise InputError("%s: empty CSV" % path)
    header = [name.strip() for name in header]
    if header[:len(CSV_HEADER)] != CSV_HEADER:
        raise InputError("%s: CSV header must start with %s" % (path, ",".join(CSV_HEADER)))
    rows = []
    for line_number, cells in enumerate(reader, 2):
        if not any(cell.strip() for cell in cells):
            continue
        where = "%s:%d" % (path, line_number)
        if len(cells) < len(CSV_HEADER):
            raise InputError("%s: %d columns, expected at least %d"
                             % (where, len(cells), len(CSV_HEADER)))
        values = {name: number(cell) for name, cell in zip(header, cells)}
        for name in CSV_HEADER[:-1]:
            if not isinstance(values[name], (int, float)):
                raise InputError("%s: %s is not a number: %r" % (where, name, values[name]))
        status = str(values.pop("status", "ok")) or "ok"
        error = str(values.pop("error", ""))
        config = {name: values.pop(name) for name in CSV_CONFIG}
        rows.append({"status": status, "error": error, "config": config,
                     "statistics": values if status == "ok" else None, "source": where})
    return rows


def load(paths):
    rows = []
    for path in paths:
        if not os.path.isfile(path):
            raise InputError("%s: no such file" % path)
        try:
            with open(path, newline="", encoding="utf-8") as handle:
                first = handle.read(4096)
                handle.seek(0)
                if path.endswith(".csv") or (not path.endswith(".jsonl")
                                             and first.lstrip()[:1] not in ("{", "")):
                    rows.extend(read_csv(path, handle))
                else:
                    rows.extend(read_jsonl(path, handle))
        except UnicodeDecodeError:
            raise InputError("%s: not UTF-8 text" % path)
        except OSError as error:
            raise InputError("%s: %s" % (path, error.strerror))
    if not rows:
        raise InputError("no rows in %s" % ", ".join(paths))
    for index, row in enumerate(rows, 1):
        row["index"] = index  # the row's number in the report's table
        row["input"] = os.path.basename(row["source"].rsplit(":", 1)[0])
        config = row["config"] = {key: config_value(value) for key, value in row["config"].items()}
        if "width" in config and "height" in config:
            config["resolution"] = "%sx%s" % (config["width"], config["height"])
    return rows


# ---------------------------------------------------------------------------------------------
# Statistics accessors (tolerant of the --stats JSON names as well)


def get(mapping, dotted, default=None):
    value = mapping
    for part in dotted.split("."):
        if not isinstance(value, dict) or part not in value:
            return default
        value = value[part]
    return value


def as_number(value):
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def fps_of(row):
    stats = row["statistics"]
    value = as_number(stats.get("fps", stats.get("frames_per_second")))
    if value is None:
        clock = as_number(row["config"].get("clock_mhz", stats.get("clock_mhz")))
        cycles = as_number(stats.get("total_cycles"))
        if clock and cycles:
            value = clock * 1e6 / cycles
    return value


def cycles_per_ray_of(row):
    stats = row["statistics"]
    value = as_number(stats.get("cycles_per_ray"))
    if value is None and as_number(stats.get("rays")) and as_number(stats.get("total_cycles")):
        value = stats["total_cycles"] / stats["rays"]
    return value


def hit_rate_of(row, level):
    return as_number(get(row["statistics"], "memory.%s.hit_rate" % level))


def per_core_times(row):
    """[(core, {busy, blocked, handover, idle} in cycles)] or None."""
    stats = row["statistics"]
    cores = stats.get("cores")
    if not isinstance(cores, list) or not cores:
        return None
    total = as_number(stats.get("total_cycles"))
    result = []
    for index, core in enumerate(cores):
        if not isinstance(core, dict):
            return None
        part = {"busy": as_number(core.get("busy")) or 0,
                "blocked": as_number(core.get("blocked")) or 0,
                "handover": as_number(core.get("handover", core.get("out"))) or 0}
        idle = as_number(core.get("idle"))
        if idle is None:
            idle = max(0, (total or 0) - sum(part.values()))
        part["idle"] = idle
        result.append((core.get("core", index), part))
    return result


def core_time_of(row):
    """Shares of all core cycles {busy, blocked, handover, idle}, summing to 1, or None."""
    share = row["statistics"].get("core_time")
    if isinstance(share, dict):
        part = {name: as_number(share.get(name, share.get("out") if name == "handover" else None))
                or 0 for name, _, _ in TIME_PARTS}
    else:
        cores = per_core_times(row)
        if not cores:
            return None
        part = {name: sum(c[1][name] for c in cores) for name, _, _ in TIME_PARTS}
    total = sum(part.values())
    if total <= 0:
        return None
    return {name: value / total for name, value in part.items()}


def wait_histogram_of(row):
    """[(wait in cycles, jobs)] sorted, or None."""
    histogram = get(row["statistics"], "scheduler.wait_histogram")
    pairs = []
    if isinstance(histogram, list):
        pairs = [(wait, jobs) for wait, jobs in enumerate(histogram)]
    elif isinstance(histogram, dict):
        for wait, jobs in histogram.items():
            try:
                pairs.append((int(wait), jobs))
            except ValueError:
                return None
    else:
        return None
    pairs = [(wait, jobs) for wait, jobs in pairs if as_number(jobs)]
    return sorted(pairs) or None


# ---------------------------------------------------------------------------------------------
# Configuration keys


def sort_key(value):
    if value is None:
        return (0, 0, "")
    if isinstance(value, bool):
        return (1, int(value), "")
    if isinstance(value, (int, float)):
        return (1, value, "")
    if isinstance(value, str) and "x" in value:
        parts = value.split("x")
        if all(p.isdigit() for p in parts):
            return (1, math.prod(int(p) for p in parts), value)
    return (2, 0, str(value))


def varied_keys(rows):
    keys = []
    for row in rows:
        for key in row["config"]:
            if key not in keys:
                keys.append(key)
    # a key some rows lack (an fps CSV has only width, height, cores) varies only if the rows
    # that have it differ
    varied = [k for k in keys
              if len({json.dumps(r["config"][k], sort_keys=True) for r in rows
                      if r["config"].get(k) is not None}) > 1]
    # width and height are shown as the resolution when that varies
    if "resolution" in varied:
        varied = [k for k in varied if k not in ("width", "height")]
    return varied


def fixed_config(rows):
    varied = set(varied_keys(rows)) if len(rows) > 1 else set()
    if "resolution" in varied:
        varied |= {"width", "height"}
    first = rows[0]["config"]
    return {k: v for k, v in first.items() if k not in varied and k != "resolution"
            and all(k in r["config"] for r in rows)}


NICE_KEYS = {"memory.l1.size": "L1 size", "memory.l2.size": "L2 size",
             "memory.dram.latency": "DRAM latency", "memory.kind": "memory",
             "clock_mhz": "clock"}


def short_key(key):
    if key in NICE_KEYS:
        return NICE_KEYS[key]
    for prefix in ("memory.",):
        if key.startswith(prefix):
            return key[len(prefix):]
    return key


def format_value(key, value):
    if value is None:
        return "-"
    if key.endswith(".size") and isinstance(value, (int, float)) and value >= 1024:
        kib = value / 1024
        return "%g MiB" % (kib / 1024) if kib >= 1024 else "%g KiB" % kib
    if key == "clock_mhz" and isinstance(value, (int, float)):
        return "%g MHz" % value
    if key.endswith("latency") and isinstance(value, (int, float)):
        return "%g cycles" % value
    if isinstance(value, float):
        return "%g" % value
    return str(value)


def describe(config, keys):
    """'key value, ...' for the keys a row has."""
    return ", ".join("%s %s" % (short_key(k), format_value(k, config.get(k))) for k in keys
                     if config.get(k) is not None)


def series_label(config, keys, default=""):
    """Legend text of a series: the value alone for one key (the legend title names it)."""
    if not keys:
        return default
    if len(keys) == 1:
        return format_value(keys[0], config.get(keys[0]))
    return textwrap.fill(describe(config, keys).replace("resolution ", ""), 34)


def legend_title(keys):
    return ", ".join(short_key(k) for k in keys) if keys else None


def title_for(what, rows, exclude=(), extra=""):
    """A title naming the scene and the fixed configuration that matters."""
    fixed = fixed_config(rows)
    fixed_keys = set(fixed)
    if "width" in fixed and "height" in fixed:
        fixed_keys.add("resolution")
    config = rows[0]["config"]
    scene = config.get("scene") if "scene" in fixed else None
    head = what + (" — scene %s" % scene if scene else "")
    items = []
    for key in TITLE_KEYS:
        if key in fixed_keys and key not in exclude:
            if key == "resolution":
                items.append("%s×%s" % (config["width"], config["height"]))
            elif key.startswith("memory.") and key != "memory.kind" \
                    and config.get("memory.kind") == "ideal":
                continue
            elif key == "cores":
                items.append("%s cores" % config[key])
            elif key == "memory.kind":
                items.append("%s memory" % config[key])
            elif key == "clock_mhz":
                items.append(format_value(key, config[key]))
            else:
                items.append(describe(config, [key]))
    if extra:
        items.append(extra)
    # break lines only between items
    sub = textwrap.fill(", ".join(i.replace(" ", "\xa0") for i in items), 85) \
        .replace("\xa0", " ") if items else ""
    return head + ("\n" + sub if sub else "")


def groups_by(rows, keys):
    """Rows grouped by the values of keys, groups and rows in value order."""
    groups = {}
    for row in rows:
        value = tuple(row["input"] if k == "input" else row["config"].get(k) for k in keys)
        groups.setdefault(value, []).append(row)
    ordered = sorted(groups.items(), key=lambda item: [sort_key(v) for v in item[0]])
    return ordered


def fmt_sig(value):
    if value == 0:
        return "0"
    if abs(value) >= 1000:
        return "{:,.0f}".format(value)
    digits = max(0, 2 - int(math.floor(math.log10(abs(value)))))
    return "%.*f" % (digits, value)


def log2_axis(ax, values, axis="x", formatter=None):
    values = sorted(set(values))
    if axis == "x":
        ax.set_xscale("log", base=2)
        target = ax.xaxis
        ax.set_xlim(values[0] / 2 ** 0.4, values[-1] * 2 ** 0.4)
    target.set_major_locator(FixedLocator(values))
    target.set_minor_locator(NullLocator())
    target.set_major_formatter(FuncFormatter(formatter or (lambda v, _: "%g" % v)))
    if len(values) > 10:
        plt.setp(target.get_majorticklabels(), rotation=45, ha="right")


def set_title(fig, text):
    fig.suptitle(text, fontsize=12)


def new_figure(width=8.0, height=5.0):
    fig, ax = plt.subplots(figsize=(width, height), layout="constrained")
    return fig, ax


def legend(ax, title=None, outside=False, **kwargs):
    handles, _ = ax.get_legend_handles_labels()
    if not handles:
        return
    if outside or len(handles) > 6:
        kwargs.pop("loc", None)
        ax.legend(title=title, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0,
                  **kwargs)
    else:
        ax.legend(title=title, **kwargs)


def label_points(ax, points):
    """Value labels above points, leaving out any that would overlap one already placed."""
    ax.autoscale_view()
    placed = []
    for x, y, color in points:
        px, py = ax.transData.transform((x, y))
        if any(abs(px - qx) < 34 and abs(py - qy) < 14 for qx, qy in placed):
            continue
        placed.append((px, py))
        ax.annotate(fmt_sig(y), (x, y), textcoords="offset points", xytext=(0, 7),
                    ha="center", fontsize=8, color=color)


def line_groups(rows, xkey, first=None):
    """(series keys, [(values, rows)], notes) for lines against xkey: rows grouped by the
    other varied keys, keeping only groups with at least two x values."""
    others = [k for k in (varied_keys(rows) if len(rows) > 1 else []) if k != xkey]
    kept = [r for _, group in groups_by(rows, others)
            if len({r["config"][xkey] for r in group}) >= 2 for r in group]
    if not kept:
        return None, [], []
    series_keys = [k for k in (varied_keys(kept) if len(kept) > 1 else []) if k != xkey]
    duplicated = any(len({r["config"][xkey] for r in group}) < len(group)
                     for _, group in groups_by(kept, series_keys))
    if duplicated and len({r["input"] for r in kept}) > 1:
        series_keys.append("input")  # the same configuration from several inputs
    if first in series_keys:
        series_keys.remove(first)
        series_keys.insert(0, first)
    notes = []
    if len(kept) < len(rows):
        notes.append("%d single points left out" % (len(rows) - len(kept)))
    groups = capped(groups_by(kept, series_keys), notes)
    return series_keys, groups, notes


def capped(groups, note_list):
    if len(groups) > MAX_LINES:
        note_list.append("first %d of %d series" % (MAX_LINES, len(groups)))
        return groups[:MAX_LINES]
    return groups


# ---------------------------------------------------------------------------------------------
# Plots: each returns [(name, figure)] (empty when it does not apply)


def plot_fps_vs_cores(rows, varied):
    rows = [r for r in rows if fps_of(r) is not None and as_number(r["config"].get("cores"))]
    if "cores" not in varied or len({r["config"]["cores"] for r in rows}) < 2:
        return []
    # resolution first, as in thesis Table 8.4
    series_keys, groups, notes = line_groups(rows, "cores", first="resolution")
    if not groups:
        return []
    rows = [r for _, group in groups for r in group]
    fig, ax = new_figure(8.5, 5.5)
    all_fps = [fps_of(r) for _, g in groups for r in g]
    log_y = min(all_fps) > 0 and max(all_fps) / min(all_fps) > 20
    points = []
    for index, (value, group) in enumerate(groups):
        group = sorted(group, key=lambda r: r["config"]["cores"])
        xs = [r["config"]["cores"] for r in group]
        ys = [fps_of(r) for r in group]
        label = series_label(dict(zip(series_keys, value)), series_keys, "frame rate")
        line, = ax.plot(xs, ys, marker=MARKERS[index % len(MARKERS)], label=label)
        points.extend((x, y, line.get_color()) for x, y in zip(xs, ys))
    log2_axis(ax, [r["config"]["cores"] for r in rows])
    if log_y:
        ax.set_yscale("log")
    ax.margins(y=0.12)
    label_points(ax, points)
    ax.set_xlabel("cores (log₂ scale)")
    ax.set_ylabel("frame rate (frames/s%s)" % (", log scale" if log_y else ""))
    set_title(fig, title_for("Frame rate against cores", rows, exclude=("cores",),
                           extra="; ".join(notes)))
    legend(ax, title=legend_title(series_keys))
    return [("fps_vs_cores", fig)]


def plot_hit_rates(rows, varied):
    cached = [r for r in rows if r["config"].get("memory.kind", get(r["statistics"], "memory.kind"))
              == "cached" and (hit_rate_of(r, "l1") is not None or hit_rate_of(r, "l2") is not None)]
    plots = []
    sub_varied = varied_keys(cached) if len(cached) > 1 else []
    for level in ("l1", "l2"):
        key = "memory.%s.size" % level
        sizes = {r["config"].get(key) for r in cached if as_number(r["config"].get(key))}
        if key not in sub_varied or len(sizes) < 2:
            continue
        points = [r for r in cached if as_number(r["config"].get(key))]
        series_keys, groups, notes = line_groups(points, key)
        if not groups:
            continue
        points = [r for _, group in groups for r in group]
        fig, ax = new_figure(8.5, 5.5)
        for index, (value, group) in enumerate(groups):
            group = sorted(group, key=lambda r: r["config"][key])
            xs = [r["config"][key] / 1024 for r in group]
            name = series_label(dict(zip(series_keys, value)), series_keys)
            for level_index, (hit_level, style) in enumerate((("l1", "-"), ("l2", "--"))):
                ys = [hit_rate_of(r, hit_level) for r in group]
                pts = [(x, 100 * y) for x, y in zip(xs, ys) if y is not None]
                if not pts:
                    continue
                color = "C%d" % (index % 10) if series_keys else "C%d" % level_index
                label = "%s hit rate" % hit_level.upper() + (" — " + name if name else "")
                ax.plot([p[0] for p in pts], [p[1] for p in pts], linestyle=style,
                        marker=MARKERS[index % len(MARKERS)], color=color, label=label)
        log2_axis(ax, [r["config"][key] / 1024 for r in points])
        ax.set_ylim(0, 105)
        ax.set_xlabel("%s cache size (KiB, log₂ scale)" % level.upper())
        ax.set_ylabel("hit rate (%)")
        set_title(fig, title_for("Cache hit rates against %s size" % level.upper(), points,
                               exclude=(key,), extra="; ".join(notes)))
        legend(ax, title=legend_title(series_keys), outside=bool(series_keys) and len(groups) > 2,
               loc="lower right")
        plots.append(("hit_rate_vs_%s_size" % level, fig))
    return plots


def plot_core_time(rows, varied):
    usable = [r for r in rows if core_time_of(r) is not None]
    if not usable:
        return []
    if len(usable) == 1:
        row = usable[0]
        cores = per_core_times(row)
        if cores:
            fig, ax = new_figure(max(6.5, min(16.0, 3.0 + 0.35 * len(cores))), 5.0)
            xs = np.arange(len(cores))
            bottom = np.zeros(len(cores))
            totals = np.array([sum(c[1].values()) for c in cores], dtype=float)
            totals[totals == 0] = 1
            for name, label, color in TIME_PARTS:
                share = np.array([c[1][name] for c in cores], dtype=float) / totals * 100
                ax.bar(xs, share, bottom=bottom, color=color, label=label, width=0.8)
                bottom += share
            ax.set_xticks(xs)
            ax.set_xticklabels([str(c[0]) for c in cores])
            if len(cores) > 32:
                for index, tick in enumerate(ax.xaxis.get_major_ticks()):
                    tick.label1.set_visible(index % 4 == 0)
            ax.set_xlim(-0.6, len(cores) - 0.4)
            ax.set_ylim(0, 100)
            ax.set_xlabel("core")
            ax.set_ylabel("share of the core's cycles (%)")
            ax.grid(axis="x", visible=False)
            set_title(fig, title_for("Time split per core", usable))
            legend(ax, outside=True)
            return [("core_time", fig)]
    labels_keys = varied
    notes = []
    if len(usable) > MAX_BARS:
        notes.append("first %d of %d configurations" % (MAX_BARS, len(usable)))
        usable = usable[:MAX_BARS]
    count = len(usable)
    labels = ["#%d  %s" % (r["index"], describe(r["config"], labels_keys)
                           .replace("resolution ", "")) for r in usable]
    longest = max(len(label) for label in labels)
    fig, ax = new_figure(min(22.0, max(9.0, 6.0 + 0.075 * longest)),
                         min(20.0, 2.4 + 0.3 * count))
    ys = np.arange(count)
    left = np.zeros(count)
    shares = [core_time_of(r) for r in usable]
    for name, label, color in TIME_PARTS:
        width = np.array([s[name] for s in shares]) * 100
        ax.barh(ys, width, left=left, color=color, label=label, height=0.75)
        left += width
    ax.set_yticks(ys)
    ax.set_yticklabels(labels, fontsize=9 if count > 20 else 10)
    ax.invert_yaxis()
    ax.set_xlim(0, 100)
    ax.set_ylim(count - 0.5, -0.5)
    ax.set_xlabel("share of all core cycles (%)")
    ax.grid(axis="y", visible=False)
    set_title(fig, title_for("Core time split per configuration", usable,
                             extra="; ".join(notes)))
    legend(ax, outside=True)
    return [("core_time", fig)]


def plot_wait_histogram(rows, varied):
    usable = [r for r in rows if wait_histogram_of(r)]
    if not usable:
        return []
    notes = []
    # Series vary one key (the scheduler if it varies, else cores, else the first varied key)
    # at the first row's values of the other varied keys.
    series_keys = []
    picked = usable
    if varied:
        for preferred in ("scheduler", "cores", "resolution") + tuple(varied):
            if preferred in varied:
                series_keys = [preferred]
                break
        others = [k for k in varied if k not in series_keys]
        anchor = usable[0]["config"]
        picked = [r for r in usable if all(r["config"].get(k) == anchor.get(k) for k in others)]
        picked = [group[0] for _, group in groups_by(picked, series_keys)]
        if others:
            notes.append("at " + describe(anchor, others))
    if len(picked) > MAX_SERIES:
        step = (len(picked) - 1) / (MAX_SERIES - 1)
        notes.append("%d of %d %s values" % (MAX_SERIES, len(picked), short_key(series_keys[0])))
        picked = [picked[round(i * step)] for i in range(MAX_SERIES)]
    histograms = [wait_histogram_of(r) for r in picked]
    max_wait = max(h[-1][0] for h in histograms)
    fig, ax = new_figure(9.0, 5.0)
    n = len(picked)
    bars = max_wait <= (64 if n <= 2 else 24)
    width = 0.8 / n
    for index, (row, histogram) in enumerate(zip(picked, histograms)):
        label = series_label(row["config"], series_keys,
                             "scheduler %s" % get(row["statistics"], "scheduler.policy", ""))
        waits = np.array([w for w, _ in histogram], dtype=float)
        jobs = np.array([j for _, j in histogram], dtype=float)
        if bars:
            ax.bar(waits + (index - (n - 1) / 2) * width, jobs, width=width, label=label,
                   color="C%d" % index)
        else:
            # outlines of bars one cycle wide; empty bins drop below the axis
            dense = np.full(max_wait + 1, 1e-3)
            dense[waits.astype(int)] = jobs
            ax.stairs(dense, np.arange(max_wait + 2) - 0.5, label=label, color="C%d" % index,
                      linewidth=1.3 + 0.6 * (n - 1 - index), baseline=None)
    ax.set_yscale("log")
    top = max(j for h in histograms for _, j in h)
    ax.set_ylim(0.5, top * 2)
    ax.set_xlim(-0.6, max_wait + 0.6)
    if bars:
        ax.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True, nbins=16))
    ax.set_xlabel("wait for a core (cycles)")
    ax.set_ylabel("jobs (log scale)")
    ax.grid(axis="x", visible=False)
    set_title(fig, title_for("Scheduler wait histogram", usable, exclude=series_keys,
                           extra="; ".join(notes)))
    legend(ax, title=legend_title(series_keys), outside=n > 3)
    return [("wait_histogram", fig)]


def plot_cycles_vs_dram(rows, varied):
    key = "memory.dram.latency"
    usable = [r for r in rows if as_number(r["config"].get(key)) is not None
              and cycles_per_ray_of(r) is not None]
    if key not in varied or len({r["config"][key] for r in usable}) < 2:
        return []
    series_keys, groups, notes = line_groups(usable, key)
    if not groups:
        return []
    usable = [r for _, group in groups for r in group]
    fig, ax = new_figure(8.5, 5.5)
    for index, (value, group) in enumerate(groups):
        group = sorted(group, key=lambda r: r["config"][key])
        label = series_label(dict(zip(series_keys, value)), series_keys, "cycles per ray")
        ax.plot([r["config"][key] for r in group], [cycles_per_ray_of(r) for r in group],
                marker=MARKERS[index % len(MARKERS)], label=label)
    latencies = sorted({r["config"][key] for r in usable})
    geometric = latencies[0] > 0 and latencies[-1] / latencies[0] >= 8
    if geometric:
        log2_axis(ax, latencies)
    elif len(latencies) <= 12:
        ax.set_xticks(latencies)
    ax.set_ylim(bottom=0)
    ax.margins(y=0.1)
    ax.set_xlabel("DRAM latency (cycles%s)" % (", log₂ scale" if geometric else ""))
    ax.set_ylabel("cycles per ray")
    set_title(fig, title_for("Cycles per ray against DRAM latency", usable, exclude=(key,),
                           extra="; ".join(notes)))
    legend(ax, title=legend_title(series_keys))
    return [("cycles_per_ray_vs_dram_latency", fig)]


PLOTS = [plot_fps_vs_cores, plot_hit_rates, plot_core_time, plot_wait_histogram,
         plot_cycles_vs_dram]


def make_plots(rows):
    ok = [r for r in rows if r["status"] == "ok" and r["statistics"] is not None]
    if not ok:
        return []
    varied = varied_keys(ok) if len(ok) > 1 else []
    figures = []
    for plot in PLOTS:
        figures.extend(plot(ok, varied))
    return figures


def render(fig, fmt):
    buffer = io.BytesIO()
    fig.savefig(buffer, format=fmt, metadata={"Date": None} if fmt == "svg" else None)
    return buffer.getvalue()


# ---------------------------------------------------------------------------------------------
# Commands


def command_plot(args):
    rows = load(args.inputs)
    figures = make_plots(rows)
    if not figures:
        ok = sum(r["status"] == "ok" for r in rows)
        raise InputError("no plot applies to %d rows (%d ok): nothing varies that a plot needs"
                         % (len(rows), ok))
    os.makedirs(args.out_dir, exist_ok=True)
    for name, fig in figures:
        for fmt in ("png", "svg"):
            path = os.path.join(args.out_dir, "%s.%s" % (name, fmt))
            with open(path, "wb") as handle:
                handle.write(render(fig, fmt))
            print(path)
        plt.close(fig)
    return 0


def cell(value):
    if value is None or value == "":
        return "<td></td>"
    if isinstance(value, float):
        text = fmt_sig(value) if abs(value) < 1e6 else "{:,.0f}".format(value)
        return '<td class="num">%s</td>' % text
    if isinstance(value, int) and not isinstance(value, bool):
        return '<td class="num">{:,}</td>'.format(value)
    return "<td>%s</td>" % html.escape(str(value))


STYLE = """
body { font-family: system-ui, -apple-system, "Segoe UI", sans-serif; margin: 2em auto;
       max-width: 1150px; padding: 0 1em; color: #222; }
h1 { font-size: 1.6em; } h2 { font-size: 1.25em; margin-top: 1.8em; border-bottom: 1px solid #ddd; }
table { border-collapse: collapse; font-size: 0.9em; margin: 0.5em 0; }
th, td { border: 1px solid #ddd; padding: 3px 8px; text-align: left; vertical-align: top; }
th { background: #f3f3f3; } td.num { text-align: right; font-variant-numeric: tabular-nums; }
tr.failed td { background: #fff0f0; } .error { color: #b00020; }
figure { margin: 1em 0; } figure img { max-width: 100%; height: auto; border: 1px solid #eee; }
figcaption { font-size: 0.85em; color: #555; }
.scroll { overflow-x: auto; } code { background: #f5f5f5; padding: 0 3px; }
"""


def command_report(args):
    rows = load(args.inputs)
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

    out.append("<h2>Fixed configuration</h2>")
    out.append('<div class="scroll"><table><tr><th>key</th><th>value</th></tr>')
    for key in sorted(fixed):
        out.append("<tr><td>%s</td>%s</tr>" % (html.escape(key), cell(fixed[key])))
    out.append("</table></div>")

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

    out.append("<h2>Rows</h2>")
    columns = ["rays", "total_cycles", "cycles_per_ray", "fps", "limit"]
    out.append('<div class="scroll"><table id="rows"><tr><th>#</th>%s%s<th>status</th></tr>' % (
        "".join("<th>%s</th>" % html.escape(k) for k in varied),
        "".join("<th>%s</th>" % c for c in columns)))
    for index, row in enumerate(rows, 1):
        stats = row["statistics"] or {}
        values = [stats.get("rays"), stats.get("total_cycles"),
                  cycles_per_ray_of(row) if stats else None, fps_of(row) if stats else None,
                  stats.get("limit")]
        status = html.escape(row["status"]) + (
            ': <span class="error">%s</span>' % html.escape(row["error"]) if row["error"] else "")
        out.append('<tr%s><td class="num">%d</td>%s%s<td>%s</td></tr>' % (
            ' class="failed"' if row["status"] != "ok" else "", index,
            "".join(cell(format_value(k, row["config"].get(k)) if k.endswith(".size")
                         else row["config"].get(k)) for k in varied),
            "".join(cell(v) for v in values), status))
    out.append("</table></div>")

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
    out.append("</body></html>\n")

    directory = os.path.dirname(os.path.abspath(args.out))
    os.makedirs(directory, exist_ok=True)
    with open(args.out, "w", encoding="utf-8") as handle:
        handle.write("\n".join(out))
    print(args.out)
    return 0


def command_frames(args):
    """Frame rate over an animation (`rtusim animate --csv`), with the share of rays the hit
    buffer saved and the jobs per traced ray beneath."""
    try:
        with open(args.csv, newline="", encoding="utf-8") as handle:
            rows = list(csv.DictReader(handle))
        frames = [int(row["frame"]) for row in rows]
        fps = [float(row["fps"]) for row in rows]
        saved = [100.0 * float(row["rays_saved"]) / max(1.0, float(row["pixels"])) for row in rows]
        jobs = [float(row["jobs_per_ray"]) for row in rows]
    except (OSError, KeyError, ValueError) as error:
        raise InputError("%s: not an animate CSV (%s)" % (args.csv, error))
    if not rows:
        raise InputError("%s: no frames" % args.csv)
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 4.6),
                                      gridspec_kw={"height_ratios": [2, 1]})
    top.plot(frames, fps, marker="o", markersize=3)
    top.set_ylabel("frames/s at the clock")
    top.set_title("frame rate over the animation")
    top.set_ylim(bottom=0)
    bottom.plot(frames, saved, color="tab:green", label="rays saved by the hit buffer (%)")
    bottom.set_ylabel("saved %")
    bottom.set_ylim(0, 100)
    twin = bottom.twinx()
    twin.plot(frames, jobs, color="tab:orange", label="jobs per traced ray")
    twin.set_ylabel("jobs/ray")
    twin.set_ylim(bottom=0)
    bottom.set_xlabel("frame")
    lines = bottom.get_lines() + twin.get_lines()
    bottom.legend(lines, [line.get_label() for line in lines], loc="upper left", fontsize=8)
    fig.tight_layout()
    directory = os.path.dirname(os.path.abspath(args.out))
    os.makedirs(directory, exist_ok=True)
    fig.savefig(args.out)
    plt.close(fig)
    print(args.out)
    return 0


class Parser(argparse.ArgumentParser):
    def error(self, message):
        self.print_usage(sys.stderr)
        sys.stderr.write("%s: error: %s\n" % (PROG, message))
        sys.exit(2)


def main(argv=None):
    parser = Parser(prog=PROG, description="Plots and an HTML report of rtusim sweep results "
                    "(JSON lines or fps CSV).")
    commands = parser.add_subparsers(dest="command", required=True, parser_class=Parser)
    plot = commands.add_parser("plot", help="write PNG and SVG plots into a directory")
    plot.add_argument("--out-dir", required=True, help="directory for the plots")
    plot.add_argument("inputs", nargs="+", metavar="INPUT", help="*.jsonl or fps *.csv")
    report = commands.add_parser("report", help="write a self-contained HTML report")
    report.add_argument("--out", required=True, help="HTML file to write")
    report.add_argument("inputs", nargs="+", metavar="INPUT", help="*.jsonl or fps *.csv")
    frames = commands.add_parser("frames", help="frame rate over an animation (rtusim animate --csv)")
    frames.add_argument("--out", required=True, help="image to write (PNG, SVG)")
    frames.add_argument("csv", metavar="FRAMES.csv", help="per-frame CSV of rtusim animate")
    args = parser.parse_args(argv)
    try:
        handlers = {"plot": command_plot, "report": command_report, "frames": command_frames}
        return handlers[args.command](args)
    except InputError as error:
        sys.stderr.write("%s: error: %s\n" % (PROG, error))
        return 2


if __name__ == "__main__":
    sys.exit(main())
