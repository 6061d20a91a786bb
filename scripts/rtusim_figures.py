"""The plots of rtusim rows (matplotlib): the objective (a statistic, fps by default) against
each varied key or --x, a line per value of --by, a panel per value of --facet; hit rates against
cache size, core time, scheduler waits, cycles per ray against DRAM latency; with --pareto, the
frame rate against a resource with its Pareto front. Each plot function
returns [(name, figure)], empty when it does not apply."""

import io
import math
import re
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import FixedLocator, FuncFormatter, NullLocator  # noqa: E402
import numpy as np  # noqa: E402

from rtusim_objective import resource_front  # noqa: E402
from rtusim_rows import (TIME_PARTS, InputError, as_number, core_time_of, cycles_per_ray_of,  # noqa: E402
                         describe, fixed_config, format_value, get, groups_by,
                         hit_rate_of, key_value, per_core_times, short_key, sort_key, value_of,
                         varied_keys, wait_histogram_of)

MAX_SERIES = 6      # wait histogram series
MAX_BARS = 48       # configurations in the core time plot
# Fixed keys worth naming in a plot title, in this order.
TITLE_KEYS = ["scheduler", "memory.kind", "clock_mhz", "resolution", "cores", "memory.l1.size",
              "memory.l2.size", "memory.dram.latency"]
MARKERS = ["o", "s", "^", "D", "v", "P", "X", "<", ">", "*"]
LINE_STYLES = ["-", "--", ":", "-."]
# Keys that split a sweep into panels by default, the first that varies.
FACET_KEYS = ["scene", "svo", "mesh", "binvox"]
# Axis labels of common statistics.
STAT_LABELS = {"fps": "frame rate (frames/s)", "frame_ms": "frame time (ms)",
               "total_cycles": "total cycles", "cycles_per_ray": "cycles per ray",
               "rays_per_second": "rays per second", "memory.l1.hit_rate": "L1 hit rate",
               "memory.l2.hit_rate": "L2 hit rate"}

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


def series_style(index):
    """Colour, marker and line style of the index-th series: distinct for 40 series."""
    return {"color": "C%d" % (index % 10), "marker": MARKERS[index % len(MARKERS)],
            "linestyle": LINE_STYLES[index // 10 % len(LINE_STYLES)]}


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



def log2_axis(ax, values):
    """A log2 x axis with a tick at each value."""
    values = sorted(set(values))
    ax.set_xscale("log", base=2)
    target = ax.xaxis
    ax.set_xlim(values[0] / 2 ** 0.4, values[-1] * 2 ** 0.4)
    target.set_major_locator(FixedLocator(values))
    target.set_minor_locator(NullLocator())
    target.set_major_formatter(FuncFormatter(lambda v, _: "%g" % v))
    if len(values) > 10:
        plt.setp(target.get_majorticklabels(), rotation=45, ha="right")


def set_title(fig, text):
    fig.suptitle(text, fontsize=12)


def new_figure(width=8.0, height=5.0):
    fig, ax = plt.subplots(figsize=(width, height), layout="constrained")
    return fig, ax


def legend_columns(entries):
    """A legend taller than its figure collapses the axes (constrained layout): 16 a column."""
    return math.ceil(entries / 16)


def widen_for_legend(fig, labels):
    """Widens a figure by the legend outside its axes, which would else squeeze them."""
    longest = max(len(line) for label in labels for line in str(label).split("\n"))
    columns = legend_columns(len(labels))
    fig.set_figwidth(fig.get_figwidth() + columns * (0.7 + 0.07 * longest))


def legend(ax, title=None, outside=False, **kwargs):
    handles, labels = ax.get_legend_handles_labels()
    if not handles:
        return
    if outside or len(handles) > 6:
        kwargs.pop("loc", None)
        widen_for_legend(ax.figure, labels)
        ax.legend(title=title, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0,
                  ncol=legend_columns(len(handles)), **kwargs)
    else:
        ax.legend(title=title, **kwargs)


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
        notes.append("%d single points left out (plot them with --x)" % (len(rows) - len(kept)))
    return series_keys, groups_by(kept, series_keys), notes



# ---------------------------------------------------------------------------------------------
# Plots: each returns [(name, figure)] (empty when it does not apply)


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
        notes.append("first %d of %d configurations (select with --where KEY=VALUE)"
                     % (MAX_BARS, len(usable)))
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
            notes.append("at " + describe(anchor, others) + " (others with --where KEY=VALUE)")
    if len(picked) > MAX_SERIES:
        step = (len(picked) - 1) / (MAX_SERIES - 1)
        notes.append("%d of %d %s values (select with --where KEY=VALUE)"
                     % (MAX_SERIES, len(picked), short_key(series_keys[0])))
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
                label=label, **series_style(index))
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


class PlotRequest:
    """What `rtusim plot` was asked for: --x, --y, --by, --facet (None: chosen from the rows),
    --pareto (a resource: only the Pareto plot of --y against it)."""

    def __init__(self, x=None, y=None, by=None, facet=None, pareto=None):
        self.x, self.y, self.by, self.facet = x, y, by, facet
        self.pareto = pareto


def default_statistic(rows):
    for name in ("fps", "frame_ms", "cycles_per_ray"):
        if all(as_number(value_of(r, name)) is not None for r in rows):
            return name
    return "fps"


def default_facet(varied):
    return next((key for key in FACET_KEYS if key in varied), None)


def default_by(x, varied, facet):
    """The inputs when several are compared, else the varied key after x (wrapping round)."""
    others = [k for k in varied if k not in (x, facet)]
    if "input" in others:
        return "input"
    after = [k for k in varied[varied.index(x) + 1:] + varied if k in others] if x in varied \
        else others
    return after[0] if after else None


def chosen(value, default):
    """An option's value: None when not given (the default), None for `none`."""
    if value is None:
        return default
    return None if value == "none" else value


def numeric_axis(ax, values, key):
    """Places x values on a numeric axis, log2 when they span a factor of 8 or more."""
    geometric = values[0] > 0 and values[-1] / values[0] >= 8
    if geometric:
        ax.set_xscale("log", base=2)
        ax.set_xlim(values[0] / 2 ** 0.4, values[-1] * 2 ** 0.4)
        ax.xaxis.set_minor_locator(NullLocator())
    ax.set_xticks(values)
    ax.set_xticklabels([format_value(key, v) for v in values])
    return " (log₂ scale)" if geometric else ""


def stat_label(name):
    path = name.replace("/", ".")
    return STAT_LABELS.get(path, path)


def plot_stat_against(rows, varied, request, x):
    """request.y against x, one line per value of `by` (the other varied keys, if any, as
    further lines: every row is drawn), one panel per value of the facet key."""
    y = request.y or default_statistic(rows)
    facet = chosen(request.facet, default_facet(varied))
    by = chosen(request.by, default_by(x, varied, facet))
    usable = [r for r in rows if as_number(value_of(r, y)) is not None
              and key_value(r, x) is not None]
    if not usable:
        return []
    series_keys = ([by] if by else []) + [k for k in varied if k not in (x, by, facet)]
    values = sorted({key_value(r, x) for r in usable}, key=sort_key)
    numeric = all(as_number(v) is not None for v in values)
    position = (lambda v: v) if numeric else (lambda v: values.index(v))
    panels = groups_by(usable, [facet]) if facet else [((), usable)]
    series = [value for value, _ in groups_by(usable, series_keys)]
    columns = min(3, len(panels))
    rows_of_panels = math.ceil(len(panels) / columns)
    fig, axes = plt.subplots(rows_of_panels, columns, squeeze=False, layout="constrained",
                             figsize=(4.8 * columns + 0.6, 4.2 * rows_of_panels + 0.8))
    for ax in axes.flat[len(panels):]:
        ax.set_visible(False)
    for ax, (panel, panel_rows) in zip(axes.flat, panels):
        for value, group in groups_by(panel_rows, series_keys):
            index = series.index(value)
            group = sorted(group, key=lambda r: sort_key(key_value(r, x)))
            line, = ax.plot([position(key_value(r, x)) for r in group],
                            [value_of(r, y) for r in group],
                            label=series_label(dict(zip(series_keys, value)), series_keys, y),
                            **series_style(index))
            line.set_gid("series %d" % index)  # one per line in the SVG, for the tests
        scale = numeric_axis(ax, values, x) if numeric else ""
        if not numeric:
            ax.set_xticks(range(len(values)))
            ax.set_xticklabels([format_value(x, v) for v in values])
            ax.set_xlim(-0.4, len(values) - 0.6)
        ax.set_xlabel(short_key(x) + scale)
        ax.set_ylabel(stat_label(y))
        ax.margins(y=0.12)
        if facet:
            ax.set_title(describe({facet: panel[0]}, [facet]))
    handles, labels = axes.flat[0].get_legend_handles_labels()
    for ax in list(axes.flat)[1:len(panels)]:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            if label not in labels:
                handles.append(handle)
                labels.append(label)
    if series_keys:
        order = sorted(range(len(labels)), key=lambda i: int(handles[i].get_gid().split()[1]))
        # on the first row's last panel, outside it
        widen_for_legend(fig, labels)
        axes[0, -1].legend([handles[i] for i in order], [labels[i] for i in order],
                           title=legend_title(series_keys), loc="upper left",
                           bbox_to_anchor=(1.02, 1.0), borderaxespad=0,
                           ncol=legend_columns(len(labels)))
    what = "%s against %s" % (stat_label(y)[0].upper() + stat_label(y)[1:], short_key(x))
    count = "%d rows, %d lines%s" % (len(usable), len(series),
                                     " in %d panels" % len(panels) if facet else "")
    set_title(fig, title_for(what, usable, exclude=(x,) + tuple(series_keys),
                             extra=count + left_out_note(rows, usable, y, x)))
    return [("%s_vs_%s" % (file_part(y), file_part(x)), fig)]


def left_out_note(rows, usable, y, x):
    missing = len(rows) - len(usable)
    return "; %d rows without %s or %s left out" % (missing, y, x) if missing else ""


def file_part(name):
    return re.sub(r"[^A-Za-z0-9]+", "_", name).strip("_")


def check_request(rows, request):
    """A key or statistic asked for that no row has is an error naming it."""
    for option, key in (("--x", request.x), ("--by", request.by), ("--facet", request.facet)):
        if key not in (None, "none") and all(key_value(r, key) is None for r in rows):
            raise InputError("%s %s: no row has the key %s" % (option, key, key))
    if request.y and all(as_number(value_of(r, request.y)) is None for r in rows):
        raise InputError("--y %s: no ok row has a number of that name (rtusim stats --list)"
                         % request.y)


def plot_objective(rows, varied, request):
    """The objective against --x, or against each varied key but the facet."""
    check_request(rows, request)
    facet = chosen(request.facet, default_facet(varied))
    xs = [request.x] if request.x else [k for k in varied if k not in (facet, "input")]
    return [plot for x in xs for plot in plot_stat_against(rows, varied, request, x)]


# Axis labels of the resource estimate's columns (issue 30 §2, docs/comparison.md).
RESOURCE_LABELS = {"bram18k": "18 Kbit block RAMs", "dsp48e": "DSP48E slices",
                   "memory_bits": "on-chip memory (bits)", "bram_bits": "block RAM bits",
                   "multipliers": "multipliers", "adders": "adders", "dividers": "dividers",
                   "comparators": "comparators", "luts": "LUTs of the arithmetic"}
# The keys that name an architecture, the first varied one colours the Pareto plot's points.
ARCHITECTURE_KEYS = ["architecture", "core"]


def resource_axis(ax, values):
    """A log x axis when the resource spans a factor of 8 or more and none is zero."""
    low, high = min(values), max(values)
    if low > 0 and high / low >= 8:
        ax.set_xscale("log")
        ax.set_xlim(low / 1.5, high * 1.8)  # room for the last point's name
        return " (log scale)"
    ax.set_xlim(left=-0.03 * high if high > 0 else -1, right=high * 1.25 if high > 0 else 1)
    return ""


def plot_pareto(rows, varied, request, resource):
    """request.y (fps by default) against a resource of the rows' estimate (bram18k, dsp48e,
    memory_bits, ...): a point a row, coloured by --by (default the architecture or core kind
    where they vary), the Pareto front joined as a staircase and its points named by the other
    varied keys."""
    y = request.y or "fps"
    usable = [r for r in rows if as_number(value_of(r, y)) is not None
              and as_number(value_of(r, resource)) is not None]
    if not usable:
        raise InputError("--pareto %s: no ok row has both %s and %s (sweep and fps rows carry the "
                         "resource estimate under \"resources\")" % (resource, y, resource))
    by = chosen(request.by, next((k for k in ARCHITECTURE_KEYS if k in varied), None))
    fig, ax = new_figure(8.5, 5.2)
    for index, (value, group) in enumerate(groups_by(usable, [by] if by else [])):
        ax.scatter([value_of(r, resource) for r in group], [value_of(r, y) for r in group],
                   color="C%d" % (index % 10), marker=MARKERS[index % len(MARKERS)], s=36,
                   label=format_value(by, value[0]) if by else "rows", zorder=3)
    front = resource_front(usable, resource, y)
    xs, ys = [value_of(r, resource) for r in front], [value_of(r, y) for r in front]
    line, = ax.step(xs, ys, where="post", color="black", linewidth=1.2, label="Pareto front",
                    zorder=2)
    line.set_gid("pareto front")  # for the tests
    ax.scatter(xs, ys, s=140, facecolors="none", edgecolors="black", zorder=4)
    named = [k for k in varied if k != by][:3]
    for row in front:
        text = describe(row["config"], ([by] if by else []) + named)
        ax.annotate(textwrap.fill(text, 28), (value_of(row, resource), value_of(row, y)),
                    textcoords="offset points", xytext=(6, 6), fontsize=7)
    scale = resource_axis(ax, [value_of(r, resource) for r in usable])
    ax.set_xlabel(RESOURCE_LABELS.get(resource, resource) + scale)
    ax.set_ylabel(stat_label(y))
    ax.set_ylim(bottom=0, top=max(value_of(r, y) for r in usable) * 1.15)
    legend(ax, title=short_key(by) if by else None, loc="lower right")
    what = "%s against %s" % (stat_label(y)[0].upper() + stat_label(y)[1:],
                              RESOURCE_LABELS.get(resource, resource))
    extra = "%d rows, %d on the Pareto front" % (len(usable), len(front))
    set_title(fig, title_for(what, usable, exclude=tuple(varied),
                             extra=extra + left_out_note(rows, usable, y, resource)))
    return [("pareto_%s_vs_%s" % (file_part(y), file_part(resource)), fig)]


PLOTS = [plot_hit_rates, plot_core_time, plot_wait_histogram, plot_cycles_vs_dram]


def make_plots(rows, request=None):
    """The plots of the ok rows: with --x or --y only that one, else the objective against each
    varied key and every other plot that applies."""
    request = request or PlotRequest()
    ok = [r for r in rows if r["status"] == "ok" and r["statistics"] is not None]
    if not ok:
        return []
    varied = varied_keys(ok) if len(ok) > 1 else []
    if request.pareto:
        return plot_pareto(ok, varied, request, request.pareto)
    figures = plot_objective(ok, varied, request)
    if request.x or request.y:
        return figures
    for plot in PLOTS:
        figures.extend(plot(ok, varied))
    return figures


def render(fig, fmt):
    buffer = io.BytesIO()
    fig.savefig(buffer, format=fmt, metadata={"Date": None} if fmt == "svg" else None)
    return buffer.getvalue()
