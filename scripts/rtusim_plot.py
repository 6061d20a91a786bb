#!/usr/bin/env python3
"""Plots, an HTML report, the best configuration and diffs of rtusim results.

Usage:
  rtusim_plot.py plot [--x KEY] [--y STAT] [--by KEY] [--facet KEY] [--pareto RESOURCE]
                      [--where KEY=VALUE]...
                      [--label NAME]... --out-dir DIR -- INPUT...
  rtusim_plot.py report [--objective OBJ]... [--group KEY]... [--base KEY=VALUE]...
                        [--where KEY=VALUE]... [--label NAME]... --out FILE.html -- INPUT...
  rtusim_plot.py best [--objective OBJ]... [--group KEY]... [--base KEY=VALUE]... -- INPUT...
  rtusim_plot.py diff [--stat NAME]... [--changed] [--label NAME]... -- A B
  rtusim_plot.py frames --out FILE.png FRAMES.csv
  rtusim_plot.py compare --out FILE.html COMPARE.json

INPUT is a sweep or fps result as JSON lines (*.jsonl, one object per configuration row with
"status", "error", "preset", "config" and "statistics"), an fps CSV (header starting
width,height,cores,rays,total_cycles,cycles_per_ray,frame_ms,fps,limit) or a statistics file
(--stats *.json). Rows from all inputs are pooled; with several, the key `input` (the file
name, or --label) tells them apart. Modules: rtusim_rows (reading rows), rtusim_figures (the
plots), rtusim_objective (best configuration), rtusim_report (HTML), rtusim_diff.

Exit status 2 with a message for missing or malformed input, or when no plot applies.
"""

import argparse
import csv
import os
import signal
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the scripts (the source tree, /tmp)
signal.signal(signal.SIGPIPE, signal.SIG_DFL)  # `rtusim diff A B | head` ends quietly

from rtusim_diff import command_diff  # noqa: E402
from rtusim_objective import Objective, summary_lines  # noqa: E402
from rtusim_rows import InputError, load, select  # noqa: E402

PROG = "rtusim_plot"


def plotting():
    """matplotlib.pyplot, imported by the commands that draw only: best and diff need none."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import numpy  # noqa: F401 (imported here to be reported here when missing)
    except ImportError as error:  # pragma: no cover - depends on the host
        # A Python first on PATH (pyenv, venv) may lack Debian's python3-matplotlib: retry once
        # with the system interpreter.
        system = "/usr/bin/python3"
        if os.environ.get("RTUSIM_PLOT_REEXEC") != "1" and os.path.exists(system) \
                and os.path.realpath(sys.executable) != os.path.realpath(system):
            os.environ["RTUSIM_PLOT_REEXEC"] = "1"
            os.execv(system, [system] + sys.argv)
        sys.stderr.write("rtusim_plot: error: %s (install python3-matplotlib and python3-numpy)\n"
                         % error)
        sys.exit(2)
    return plt


def write_whole(path, data):
    """Writes `data` to `path` whole or not at all (docs/robustness.md, "Outputs: whole or not at
    all"): into a temporary file beside it, flushed to the disk, then renamed into place. A full
    disk or an interrupted run leaves the old file (or none), never a cut one."""
    directory = os.path.dirname(os.path.abspath(path))
    temporary = os.path.join(directory, ".%s.%d.tmp" % (os.path.basename(path), os.getpid()))
    try:
        with open(temporary, "wb") as handle:
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise


def rows_of(args):
    return select(load(args.inputs, args.label), args.where)


def objectives_of(args):
    objectives = [Objective(text) for text in (args.objective or ["fps"])]
    if len(objectives) > 2:
        raise InputError("--objective: one, or two for the Pareto front, not %d" % len(objectives))
    return objectives


def command_plot(args):
    plt = plotting()
    from rtusim_figures import PlotRequest, make_plots, render
    rows = rows_of(args)
    request = PlotRequest(args.x, args.y, args.by, args.facet, args.pareto)
    figures = make_plots(rows, request)
    if not figures:
        ok = sum(r["status"] == "ok" for r in rows)
        raise InputError("no plot applies to %d rows (%d ok): nothing varies that a plot needs"
                         % (len(rows), ok))
    os.makedirs(args.out_dir, exist_ok=True)
    for name, fig in figures:
        for fmt in ("png", "svg"):
            path = os.path.join(args.out_dir, "%s.%s" % (name, fmt))
            write_whole(path, render(fig, fmt))
            print(path)
        plt.close(fig)
    return 0


def command_best(args):
    print("\n".join(summary_lines(rows_of(args), objectives_of(args), args.group, args.base)))
    return 0


def command_frames(args):
    """Frame rate over an animation (`rtusim animate --csv`), beneath it the share of rays the hit
    buffer saved and the jobs per traced ray (the SVO scene manager's CSV), or the top level's
    build time and the instances entered per ray (the two-level BVH's, `--core bvh`)."""
    plt = plotting()
    try:
        with open(args.csv, newline="", encoding="utf-8") as handle:
            rows = list(csv.DictReader(handle))
        frames = [int(row["frame"]) for row in rows]
        fps = [float(row["fps"]) for row in rows]
        two_level = bool(rows) and "top_build_s" in rows[0]
        if two_level:
            lower = ([1e6 * float(row["top_build_s"]) for row in rows],
                     "top level's build (µs)", "build µs", None)
            upper = ([float(row["instances_per_ray"]) for row in rows],
                     "instances entered per ray", "instances/ray")
        else:
            lower = ([100.0 * float(row["rays_saved"]) / max(1.0, float(row["pixels"]))
                      for row in rows], "rays saved by the hit buffer (%)", "saved %", 100)
            upper = ([float(row["jobs_per_ray"]) for row in rows], "jobs per traced ray",
                     "jobs/ray")
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
    bottom.plot(frames, lower[0], color="tab:green", label=lower[1])
    bottom.set_ylabel(lower[2])
    bottom.set_ylim(0, lower[3])
    twin = bottom.twinx()
    twin.plot(frames, upper[0], color="tab:orange", label=upper[1])
    twin.set_ylabel(upper[2])
    twin.set_ylim(bottom=0)
    bottom.set_xlabel("frame")
    lines = bottom.get_lines() + twin.get_lines()
    bottom.legend(lines, [line.get_label() for line in lines], loc="upper left", fontsize=8)
    fig.tight_layout()
    directory = os.path.dirname(os.path.abspath(args.out))
    os.makedirs(directory, exist_ok=True)
    from rtusim_figures import render
    write_whole(args.out, render(fig, os.path.splitext(args.out)[1][1:].lower() or "png"))
    plt.close(fig)
    print(args.out)
    return 0


class Parser(argparse.ArgumentParser):
    def error(self, message):
        self.print_usage(sys.stderr)
        sys.stderr.write("%s: error: %s\n" % (PROG, message))
        sys.exit(2)


def add_rows(parser):
    parser.add_argument("--where", action="append", default=[], metavar="KEY=VALUE",
                        help="keep only the rows with this value")
    parser.add_argument("--label", action="append", default=[], help="a name per input")
    parser.add_argument("inputs", nargs="+", metavar="INPUT", help="*.jsonl, fps *.csv, *.json")


def add_objective(parser):
    parser.add_argument("--objective", action="append", default=[],
                        help="STAT, max:STAT or min:STAT (default fps); two: the Pareto front")
    parser.add_argument("--group", action="append", default=[], help="a best row per value")
    parser.add_argument("--base", action="append", default=[], metavar="KEY=VALUE",
                        help="the base configuration of the gain")


def main(argv=None):
    parser = Parser(prog=PROG, description="Plots, an HTML report, the best configuration and "
                    "diffs of rtusim results (JSON lines, fps CSV, statistics JSON).")
    commands = parser.add_subparsers(dest="command", required=True, parser_class=Parser)
    plot = commands.add_parser("plot", help="write PNG and SVG plots into a directory")
    plot.add_argument("--out-dir", required=True, help="directory for the plots")
    plot.add_argument("--x", help="the key on the x axis (default: each varied key)")
    plot.add_argument("--y", help="the statistic on the y axis (default: fps)")
    plot.add_argument("--by", help="a line per value of this key (none: no such key)")
    plot.add_argument("--facet", help="a panel per value of this key (none: one panel)")
    plot.add_argument("--pareto", metavar="RESOURCE",
                      help="only the Pareto plot of --y (fps) against this resource column "
                      "(bram18k, dsp48e, memory_bits, multipliers, luts)")
    add_rows(plot)
    report = commands.add_parser("report", help="write a self-contained HTML report")
    report.add_argument("--out", required=True, help="HTML file to write")
    add_rows(report)
    add_objective(report)
    best = commands.add_parser("best", help="the best configuration per group")
    add_rows(best)
    add_objective(best)
    diff = commands.add_parser("diff", help="two runs or sweeps side by side")
    diff.add_argument("--stat", action="append", default=[], help="only this statistic")
    diff.add_argument("--changed", action="store_true", help="only statistics that differ")
    diff.add_argument("--label", action="append", default=[], help="names of A and B")
    diff.add_argument("inputs", nargs="+", metavar="INPUT", help="two .json or .jsonl files")
    compare = commands.add_parser("compare", help="the HTML report of rtusim compare")
    compare.add_argument("--out", required=True, help="HTML file to write")
    compare.add_argument("inputs", nargs=1, metavar="COMPARE.json", help="rtusim compare --json")
    frames = commands.add_parser("frames", help="frame rate over an animation (rtusim animate --csv)")
    frames.add_argument("--out", required=True, help="image to write (PNG, SVG)")
    frames.add_argument("csv", metavar="FRAMES.csv", help="per-frame CSV of rtusim animate")
    args = parser.parse_args(argv)
    try:
        if args.command == "report":
            plotting()
            from rtusim_report import command_report
            return command_report(args, objectives_of(args), rows_of(args))
        if args.command == "compare":
            from rtusim_compare import command_compare
            return command_compare(args, plotting())
        handlers = {"plot": command_plot, "best": command_best, "diff": command_diff,
                    "frames": command_frames}
        return handlers[args.command](args)
    except InputError as error:
        sys.stderr.write("%s: error: %s\n" % (PROG, error))
        return 2


if __name__ == "__main__":
    sys.exit(main())
