"""The best configuration of rtusim rows by an objective: per group of the workload keys (scene,
resolution, input, ...), the best row, its gain over the base configuration, and with two
objectives the Pareto front."""

from rtusim_rows import (WORKLOAD_KEYS, InputError, as_number, config_value, describe,
                         format_value, groups_by, key_value, number, short_key,
                         value_of, varied_keys)

# Directions of objectives named without max: or min:.
MAXIMISED = ("fps", "rays_per_second", "hit_rate")
MINIMISED = ("frame_ms", "total_cycles", "cycles_per_ray", "cores", "size", "bytes", "latency")


class Objective:
    def __init__(self, text):
        direction, colon, name = text.partition(":")
        if colon and direction in ("max", "min"):
            self.name, self.maximise = name, direction == "max"
        elif text.split(".")[-1].endswith(MAXIMISED):
            self.name, self.maximise = text, True
        elif text.split(".")[-1].endswith(MINIMISED):
            self.name, self.maximise = text, False
        else:
            raise InputError("--objective %s: say max:%s or min:%s" % (text, text, text))

    def value(self, row):
        return as_number(value_of(row, self.name))

    def better(self, a, b):
        """a strictly better than b."""
        return a > b if self.maximise else a < b

    def gain(self, best, base):
        """How much better best is than base as a share: the rate's rise (fps 110 over 100:
        +10 %), for a cost its fall read as a rate (frame time 100 over 110 ms: +10 %)."""
        if not base or not best:
            return None
        return best / base - 1 if self.maximise else base / best - 1

    def describe(self):
        return "%s (%s is better)" % (self.name, "higher" if self.maximise else "lower")


def group_keys(rows, given):
    varied = varied_keys(rows) if len(rows) > 1 else []
    return list(given) if given else [k for k in WORKLOAD_KEYS if k in varied]


def base_values(rows, groups, given):
    """The base configuration: --base KEY=VALUE, the other varied keys at the first row's."""
    varied = [k for k in (varied_keys(rows) if len(rows) > 1 else []) if k not in groups]
    base = {key: key_value(rows[0], key) for key in varied}
    for condition in given:
        key, equals, text = condition.partition("=")
        if not equals:
            raise InputError("--base takes KEY=VALUE, got %r" % condition)
        base[key] = config_value(number(text))
    return base


def pareto_front(rows, objectives):
    """The rows no other row beats on one objective without losing on another."""
    def dominates(a, b):
        return all(not o.better(o.value(b), o.value(a)) for o in objectives) and \
            any(o.better(o.value(a), o.value(b)) for o in objectives)
    return [r for r in rows if not any(dominates(other, r) for other in rows)]


def resource_front(rows, resource, rate):
    """The Pareto front of `rate` (fps) against a resource (bram18k): the rows no other row beats
    with no more of the resource and no lower rate, by the resource."""
    front = pareto_front(rows, [Objective("min:" + resource), Objective("max:" + rate)])
    return sorted(front, key=lambda r: (value_of(r, resource), -value_of(r, rate)))


def summaries(rows, objectives, groups_given=(), base_given=()):
    """Per group: {"group": {key: value}, "best": row, "ties": rows as good, "base": row or
    None, "gain": share or None, "front": rows (two objectives), "rows": count}."""
    ok = [r for r in rows if r["status"] == "ok" and objectives[0].value(r) is not None]
    if not ok:
        raise InputError("no ok row has %s" % objectives[0].name)
    groups = group_keys(ok, groups_given)
    base = base_values(ok, groups, base_given)
    result = []
    for value, members in groups_by(ok, groups):
        objective = objectives[0]
        best = members[0]
        for row in members[1:]:
            if objective.better(objective.value(row), objective.value(best)):
                best = row
        ties = [r for r in members if r is not best and objective.value(r) == objective.value(best)]
        base_row = next((r for r in members
                         if all(key_value(r, k) == v for k, v in base.items())), None)
        usable = [r for r in members if all(o.value(r) is not None for o in objectives)]
        result.append({"group": dict(zip(groups, value)), "best": best, "ties": ties,
                       "base": base_row, "base_values": base, "rows": len(members),
                       "gain": objective.gain(objective.value(best), objective.value(base_row))
                       if base_row else None,
                       "front": pareto_front(usable, objectives) if len(objectives) > 1 else []})
    return result


def objective_text(value):
    """Five digits: gains of a few per cent show in the values compared."""
    return "%.5g" % value


def row_name(row, keys):
    return "#%d %s" % (row["index"], describe(row["config"], keys) or "(the only configuration)")


def format_gain(gain):
    return "-" if gain is None else "%+.2f %%" % (100 * gain)


def summary_lines(rows, objectives, groups_given=(), base_given=()):
    """The summary as text lines, for `rtusim best`."""
    found = summaries(rows, objectives, groups_given, base_given)
    objective = objectives[0]
    first = found[0]
    keys = list(first["base_values"])
    base = describe(first["base_values"], keys) or "the only configuration"
    lines = ["objective: %s; base: %s (%s); gain: the rate's rise over the base"
             % (objective.describe(), base,
                "--base" if base_given else "the first row's values, or say --base KEY=VALUE")]
    for summary in found:
        where = describe(summary["group"], list(summary["group"])) or "all rows"
        best = summary["best"]
        line = "%s: best %s: %s %s" % (where, row_name(best, keys), objective.name,
                                       objective_text(objective.value(best)))
        if summary["ties"]:
            line += " (as good: %s)" % ", ".join("#%d" % r["index"] for r in summary["ties"])
        if summary["base"] is None:
            line += "; no row has the base configuration"
        else:
            line += "; base #%d %s: gain %s" % (summary["base"]["index"],
                                                 objective_text(objective.value(summary["base"])),
                                                 format_gain(summary["gain"]))
        lines.append(line)
        if summary["front"]:
            lines.append("  Pareto front of %s (%d of %d rows):" % (
                " and ".join(o.describe() for o in objectives), len(summary["front"]),
                summary["rows"]))
            for row in sorted(summary["front"], key=lambda r: objective.value(r),
                              reverse=objective.maximise):
                lines.append("    %s: %s" % (row_name(row, keys), ", ".join(
                    "%s %s" % (short_key(o.name), objective_text(o.value(row)) if isinstance(
                        o.value(row), float) else format_value(o.name, o.value(row)))
                    for o in objectives)))
    return lines
