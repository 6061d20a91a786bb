#!/usr/bin/env python3
"""Prints a VCD file as its value changes, one "cycle signal value" line each, in cycle and
signal order: the form in which two traces of the same run must be equal whatever order or
redundancy their writers chose. A change to the value a signal already holds is dropped, and
'x' is written as x. Usage: vcd_normalise.py trace.vcd period_ps"""
import sys


def changes(path):
    codes, scopes, time = {}, [], 0
    definitions = True
    with open(path) as vcd:
        for line in vcd:
            words = line.split()
            if not words:
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
                time = int(head[1:])
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
