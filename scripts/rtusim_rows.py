"""Rows of rtusim runs as the plots, report, best-configuration summary and diff read them:
sweep or fps rows as JSON lines (*.jsonl: "status", "error", "preset", "config", "statistics"),
an fps CSV, or a statistics file (--stats *.json); their statistics by name, and their
configuration keys: which vary, which are fixed, how a value is written."""

import csv
import json
import math
import os
import re

CSV_HEADER = ["width", "height", "cores", "rays", "total_cycles", "cycles_per_ray", "frame_ms",
              "fps", "limit"]
CSV_CONFIG = ["width", "height", "cores"]
# An fps CSV's columns under the names of the statistics JSON.
CSV_NAMES = {"memory.l1.hit_rate": "l1_hit_rate", "memory.l2.hit_rate": "l2_hit_rate",
             "core_time.busy": "core_busy", "core_time.blocked": "core_blocked",
             "core_time.handover": "core_handover", "core_time.idle": "core_idle",
             "core_time.triangle_unit_stall": "core_unit_stall",
             "memory.dram.bytes": "dram_bytes", "cost.mean": "cost_mean",
             "blocked_cycles.mean": "blocked_mean", "scheduler.max_wait": "max_wait"}
TIME_PARTS = [("busy", "busy", "#2b8a3e"), ("blocked", "blocked", "#e8590c"),
              ("handover", "waiting to hand over", "#1c7ed6"), ("idle", "idle", "#adb5bd")]
# Keys of the workload rather than of the hardware: a best configuration is chosen per value.
WORKLOAD_KEYS = ["input", "scene", "svo", "mesh", "binvox", "resolution", "rays", "jobs",
                 "camera.position", "camera.look_at", "camera.fov"]


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


def run_row(obj, where):
    """A row of a run's JSON object: a sweep or fps row, or a statistics file (--stats)."""
    if not isinstance(obj, dict):
        raise InputError("%s: expected a JSON object" % where)
    config = obj.get("config")
    if not isinstance(config, dict):
        raise InputError("%s: no \"config\" object" % where)
    status = obj.get("status", "ok" if "statistics" in obj else "failed")
    statistics = obj.get("statistics")
    if status == "ok" and not isinstance(statistics, dict):
        raise InputError("%s: status ok but no \"statistics\" object" % where)
    # the architecture's resource estimate (issue 30 §2): its totals, not its itemised lists
    resources = obj.get("resources") if isinstance(obj.get("resources"), dict) else {}
    return {"status": str(status), "error": str(obj.get("error") or ""),
            "preset": str(obj.get("preset") or ""), "config": flatten(config),
            "statistics": statistics if status == "ok" else None, "source": where,
            "resources": {k: v for k, v in resources.items() if not isinstance(v, (dict, list))}}


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
        rows.append(run_row(obj, where))
    return rows


def read_json(path, handle):
    """A statistics file (render or replay --stats): one run."""
    try:
        obj = json.load(handle)
    except json.JSONDecodeError as error:
        raise InputError("%s: not JSON: %s" % (path, error.msg))
    return [run_row(obj, path)]


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
        rows.append({"status": status, "error": error, "preset": "", "config": config,
                     "statistics": values if status == "ok" else None, "source": where})
    return rows


def read_file(path):
    if not os.path.isfile(path):
        raise InputError("%s: no such file" % path)
    try:
        with open(path, newline="", encoding="utf-8") as handle:
            first = handle.read(4096).lstrip()
            handle.seek(0)
            if path.endswith(".csv") or (not path.endswith((".json", ".jsonl"))
                                         and first[:1] not in ("{", "")):
                return read_csv(path, handle)
            # a statistics file is one object over many lines, a .jsonl one object a line
            if path.endswith(".json") or (not path.endswith(".jsonl") and first[:2] == "{\n"):
                return read_json(path, handle)
            return read_jsonl(path, handle)
    except UnicodeDecodeError:
        raise InputError("%s: not UTF-8 text" % path)
    except OSError as error:
        raise InputError("%s: %s" % (path, error.strerror))


def load(paths, labels=None):
    """The rows of all inputs, pooled. With several inputs, each row's configuration gains the
    key `input`: its label (--label, in the inputs' order) or file name, so that the inputs can
    be compared like any varied key."""
    labels = list(labels or [])
    if len(labels) > len(paths):
        raise InputError("%d labels for %d inputs" % (len(labels), len(paths)))
    names = labels + [os.path.basename(path) for path in paths[len(labels):]]
    if len(set(names)) < len(names):
        raise InputError("two inputs have the name %s: name them with --label"
                         % next(n for n in names if names.count(n) > 1))
    rows = []
    for path, name in zip(paths, names):
        for number_in_input, row in enumerate(read_file(path), 1):
            row["input"], row["number_in_input"] = name, number_in_input
            rows.append(row)
    if not rows:
        raise InputError("no rows in %s" % ", ".join(paths))
    for index, row in enumerate(rows, 1):
        row["index"] = index  # the row's number in the report's table
        config = row["config"] = {key: config_value(value) for key, value in row["config"].items()}
        if "width" in config and "height" in config:
            config["resolution"] = "%sx%s" % (config["width"], config["height"])
        if len(paths) > 1:
            config["input"] = row["input"]
    return rows


def key_value(row, key):
    """A configuration key's value in a row; `preset` is the preset the row started from."""
    return row["preset"] if key == "preset" else row["config"].get(key)


def select(rows, conditions):
    """The rows with KEY=VALUE for every condition (--where), values compared as rtusim writes
    them (4KiB equals 4096)."""
    for condition in conditions:
        key, equals, text = condition.partition("=")
        if not equals or not key:
            raise InputError("--where takes KEY=VALUE, got %r" % condition)
        if not any(key == "preset" or key in row["config"] for row in rows):
            raise InputError("--where %s: no row has the key %s" % (condition, key))
        wanted = config_value(number(text))
        rows = [row for row in rows if key_value(row, key) == wanted
                or str(key_value(row, key)) == text]
        if not rows:
            raise InputError("--where %s: no row is left" % condition)
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


def statistic(row, name):
    """A statistic of an ok row by its name in `rtusim stats --list` (utilisation/cores) or its
    JSON path (utilisation.cores); an fps CSV's column by either name too. None when absent."""
    stats = row["statistics"] or {}
    path = name.replace("/", ".")
    if path in stats:
        return stats[path]
    value = get(stats, path)
    return stats.get(CSV_NAMES.get(path)) if value is None else value


def value_of(row, name):
    """A statistic, a resource of the row's estimate (bram18k, dsp48e), or else a configuration
    key, of a row (an objective or an axis may be either: fps, or memory.l1.size as a cost)."""
    value = statistic(row, name)
    if value is None:
        value = row.get("resources", {}).get(name)
    # `cores` is the per-core statistics and the setting: the setting is the number
    return key_value(row, name) if value is None or isinstance(value, (dict, list)) else value


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


def input_keys(rows):
    """Keys that differ between inputs but not within any (the base configuration of each): they
    vary only as the key `input` does."""
    if not any("input" in r["config"] for r in rows):
        return []
    per_input = {}
    for row in rows:
        for key, value in row["config"].items():
            per_input.setdefault(key, {}).setdefault(row["input"], set()).add(
                json.dumps(value, sort_keys=True))
    return [key for key, inputs in per_input.items() if key != "input"
            and all(len(values) == 1 for values in inputs.values())
            and len(set().union(*inputs.values())) > 1]


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
    by_input = input_keys(rows)
    varied = [k for k in varied if k not in by_input]
    # width and height are shown as the resolution when that varies
    if "resolution" in varied:
        varied = [k for k in varied if k not in ("width", "height")]
    return varied


def fixed_config(rows):
    varied = set(varied_keys(rows) + input_keys(rows)) if len(rows) > 1 else set()
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

