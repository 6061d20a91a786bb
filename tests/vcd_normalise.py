#!/usr/bin/env python3
"""Prints a VCD file as its value changes, one "cycle signal value" line each, in cycle and
signal order: the form in which two traces of the same run must be equal whatever order or
redundancy their writers chose. A change to the value a signal already holds is dropped, and
'x' is written as x. Times are read in the file's $timescale (cycles or picoseconds: rtusim's
--trace-time). Usage: vcd_normalise.py trace.vcd period_ps"""
import re
import sys

UNIT_PS = {"ps": 1, "ns": 10**3, "us": 10**6, "ms": 10**9, "s": 10**12}


def timescale_ps(text):
    """Picoseconds of a $timescale such as "10ns" or "1 ps"."""
    match = re.fullmatch(r"(1|10|100)\s*(ps|ns|us|ms|s)", text.strip())
    if not match:
        raise SystemExit(f"unsupported $timescale {text!r}")
    return int(match.group(1)) * UNIT_PS[match.group(2)]


def changes(path):
    """(time in ps, signal, bits) of each value change."""
    codes, scopes, time, unit = {}, [], 0, 1
    definitions, timescale = True, None
    with open(path) as vcd:
        for line in vcd:
            words = line.split()
            if not words:
                continue
            if timescale is not None or words[0] == "$timescale":
                timescale = (timescale or []) + [w for w in words if w not in ("$timescale", "$end")]
                if "$end" in words:
                    unit, timescale = timescale_ps("".join(timescale)), None
                continue
            if definitions:
                if words[0] == "$scope":
                    scopes.append(words[2])
                elif words[0] == "$upscope":
                    scopes.pop()
                elif words[0] == "$var":
                    codes[words[3]] = ".".join(scopes + [words[4]])
                elif words[0] == "$enddefinitions":
                    definitions = False
                continue
            head = words[0]
            if head[0] == "#":
                time = int(head[1:]) * unit
            elif head[0] == "b":
                yield time, codes[words[1]], head[1:]
            elif head[0] in "01xz":
                yield time, codes[head[1:]], head[0]


def main():
    path, period = sys.argv[1], int(sys.argv[2])
    final = {}  # (cycle, signal) -> its last value in file order
    for time, name, bits in changes(path):
        final[(time // period, name)] = "x" if "x" in bits else str(int(bits, 2))
    held, out = {}, []
    for (cycle, name), value in sorted(final.items()):
        if held.get(name) != value:
            held[name] = value
            out.append("%d %s %s\n" % (cycle, name, value))
    sys.stdout.write("".join(out))


main()
