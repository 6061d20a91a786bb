"""Two runs side by side (`rtusim diff A B`): two statistics files or two sweeps. The keys of the
configuration that differ come first, then every statistic of each pair of rows with the
difference B - A and the ratio B / A. Rows of two sweeps pair by their configuration apart from
the keys that differ between the sweeps as a whole."""

import json

from rtusim_rows import (InputError, as_number, describe, fmt_sig, format_value, input_keys, load,
                         sort_key)


def flat_statistics(value, prefix=""):
    """{path: value} of every leaf, objects and arrays alike (cores.3.busy)."""
    if isinstance(value, dict):
        items = value.items()
    elif isinstance(value, list):
        items = enumerate(value)
    else:
        return {prefix: value}
    flat = {}
    for key, item in items:
        flat.update(flat_statistics(item, "%s.%s" % (prefix, key) if prefix else str(key)))
    return flat


def pairing_key(row, skipped):
    return json.dumps({k: v for k, v in row["config"].items() if k not in skipped and k != "input"},
                      sort_keys=True)


def paired_rows(rows):
    """(keys that differ between the inputs, [(row of A or None, row of B or None)])."""
    names = list(dict.fromkeys(r["input"] for r in rows))
    differing = input_keys(rows)
    a = {pairing_key(r, differing): r for r in rows if r["input"] == names[0]}
    b = {pairing_key(r, differing): r for r in rows if r["input"] == names[1]}
    return differing, [(a.get(key), b.get(key)) for key in dict.fromkeys(list(a) + list(b))]


def swept_differently(rows, names, differing):
    """{key: (A's values, B's values)} of the keys with other sets of values in A and B, beyond
    those that differ as a whole (rows of such values pair with none)."""
    result = {}
    for key in dict.fromkeys(k for r in rows for k in r["config"]):
        if key in differing or key in ("input", "width", "height"):
            continue
        sets = [sorted({json.dumps(r["config"].get(key)): r["config"].get(key) for r in rows
                        if r["input"] == name}.values(), key=sort_key) for name in names]
        if sets[0] != sets[1]:
            result[key] = tuple(", ".join(format_value(key, v) for v in values) for values in sets)
    return result


def number_text(value):
    if isinstance(value, bool) or value is None:
        return str(value).lower() if isinstance(value, bool) else "-"
    if isinstance(value, float):  # six digits: a difference of a per mille shows
        return "{:,.0f}".format(value) if abs(value) >= 1e6 else "%.6g" % value
    return str(value)


def statistic_lines(a, b, only, changed):
    """Lines of every statistic of rows a and b: name, A, B, B - A, B / A."""
    flat_a, flat_b = flat_statistics(a["statistics"] or {}), flat_statistics(b["statistics"] or {})
    lines = []
    for name in dict.fromkeys(list(flat_a) + list(flat_b)):
        if only and not any(name == o or name.startswith(o + ".") for o in only):
            continue
        va, vb = flat_a.get(name), flat_b.get(name)
        if changed and va == vb:
            continue
        na, nb = as_number(va), as_number(vb)
        difference = ratio = ""
        if na is not None and nb is not None:
            difference = fmt_sig(nb - na) if isinstance(nb - na, float) else "%+d" % (nb - na)
            ratio = "%.4f" % (nb / na) if na else ("-" if nb == 0 else "inf")
        elif va != vb:
            difference = "differs"
        lines.append("  %-40s %16s %16s %14s %9s" % (name, number_text(va), number_text(vb),
                                                      difference, ratio))
    return lines


def diff_lines(paths, labels, only, changed):
    rows = load(paths, labels)
    names = list(dict.fromkeys(r["input"] for r in rows))
    differing, pairs = paired_rows(rows)
    first = {name: next(r for r in rows if r["input"] == name) for name in names}
    lines = ["A: %s, B: %s" % tuple(names), "configuration differences:"]
    single = len(rows) == 2  # two runs: no row headings
    for key in differing:
        lines.append("  %-40s %16s %16s" % (key, format_value(key, first[names[0]]["config"].get(key)),
                                             format_value(key, first[names[1]]["config"].get(key))))
    swept = swept_differently(rows, names, differing)
    for key, (values_a, values_b) in swept.items():
        lines.append("  %-40s A: %s; B: %s" % (key, values_a, values_b))
    if not differing and not swept:
        lines.append("  none")
    header = "  %-40s %16s %16s %14s %9s" % ("statistic", "A", "B", "B - A", "B / A")
    varied = sorted({k for a, b in pairs for r in (a, b) if r for k in r["config"]
                     if k not in differing and k not in ("input", "width", "height")
                     and len({json.dumps(x["config"].get(k)) for x in rows}) > 1})
    for a, b in pairs:
        which = describe((a or b)["config"], varied)
        if a is None or b is None:
            lines.append("row %s: only in %s" % (which, "B" if a is None else "A"))
            continue
        if not single:
            lines.append("row %s (A #%d, B #%d):" % (which or "-", a["number_in_input"],
                                                     b["number_in_input"]))
        if a["status"] != "ok" or b["status"] != "ok":
            lines.append("  status %s / %s" % (a["status"], b["status"]))
            continue
        lines.append(header)
        lines.extend(statistic_lines(a, b, only, changed))
    return lines


def command_diff(args):
    if len(args.inputs) != 2:
        raise InputError("diff takes two files, got %d" % len(args.inputs))
    print("\n".join(diff_lines(args.inputs, args.label, args.stat, args.changed)))
    return 0
