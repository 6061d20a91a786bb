#!/usr/bin/env python3
"""Checks what a unity build (RTUSIM_UNITY_BUILD, docs/architecture.md) would break: a .cpp file
of a batched target (the command, rtusim_explore, rtusim_config, the tests) that defines a type at
namespace scope whose name another such file, or any header under src/ or tests/, also defines.
Batches are made by file order, so a clash appears or hides as files are added; the compiler sees
one only in the batch that pairs the two. Functions are not checked (overloads are legitimate).
Prints each clash with its files and exits 1; exits 0 when every such type name is unique."""
import collections
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent)
# A type defined at column 0 (namespace scope in this tree's style), not a forward declaration.
definition = re.compile(r"^(?:template\s*<[^>]*>\s*)?(?:struct|class|enum class|enum|union)\s+"
                        r"(\w+)\b(?!::)[^;]*(?:\{|$)")
specialisation = re.compile(r"^(?:struct|class)\s+\w+\s*<")


def defined(path):
    names = set()
    for line in path.read_text().splitlines():
        match = definition.match(line)
        if match and not specialisation.match(line) and not line.rstrip().endswith(";"):
            names.add(match.group(1))
    return names


batched = [p for folder in ("src/app", "src/explore", "src/config", "tests")
           for p in sorted((root / folder).glob("*.cpp"))]
batched += sorted((root / "src/kinds").glob("*/app/*.cpp"))
batched += sorted((root / "src/kinds").glob("*/explore/*.cpp"))
headers = sorted((root / "src").rglob("*.h")) + sorted((root / "tests").rglob("*.h"))

owners = collections.defaultdict(set)
for path in batched + headers:
    for name in defined(path):
        owners[name].add(path.relative_to(root).as_posix())
clashes = {name: files for name, files in owners.items()
           if len(files) > 1 and any(f.endswith(".cpp") for f in files)}
for name, files in sorted(clashes.items()):
    print(f"type {name} is defined in several files a unity batch may join: {', '.join(sorted(files))}")
sys.exit(1 if clashes else 0)
