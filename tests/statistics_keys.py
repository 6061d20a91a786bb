#!/usr/bin/env python3
"""Prints the keys of the "statistics" of run JSON files (`--stats` files, or sweep and fps rows
as JSON lines), one a line, sorted: a key nests objects with '/', parts of an array of objects
are '*' ("cores/*/jobs"), and arrays of numbers are values ("scheduler/wait_histogram")."""
import json
import sys


def walk(value, key, keys):
    if isinstance(value, dict):
        for name, inner in value.items():
            walk(inner, f"{key}/{name}" if key else name, keys)
    elif isinstance(value, list) and value and all(isinstance(part, dict) for part in value):
        for part in value:
            walk(part, key + "/*", keys)
    else:
        keys.add(key)


keys = set()
for path in sys.argv[1:]:
    text = open(path).read()
    runs = [json.loads(line) for line in text.splitlines() if line.strip()] \
        if path.endswith(".jsonl") else [json.loads(text)]
    for run in runs:
        walk(run["statistics"], "", keys)
print("\n".join(sorted(keys)))
