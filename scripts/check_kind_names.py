#!/usr/bin/env python3
"""Checks that no two core kinds' folders (src/kinds/*/) declare a type of the same name at
namespace scope. Kinds never include each other, so the compiler cannot see such a clash, but the
program links every kind: two different `rtu::FixedFormat`s would break the one-definition rule
and an inline member of one could silently stand in for the other's. Prints each clash with the
files declaring it and exits 1; exits 0 when every type name belongs to one kind."""
import collections
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent)
declaration = re.compile(r"^(?:template\s*<[^>]*>\s*)?(?:struct|class|enum class|enum|union|using)"
                         r"\s+(\w+)\b(?!\s*;)")
declared = collections.defaultdict(set)
for path in sorted((root / "src" / "kinds").glob("*/*.h")):
    for line in path.read_text().splitlines():
        match = declaration.match(line)
        if match:
            declared[match.group(1)].add(path.relative_to(root).as_posix())
clashes = {name: files for name, files in declared.items()
           if len({pathlib.PurePosixPath(f).parent for f in files}) > 1}
for name, files in sorted(clashes.items()):
    print(f"type {name} is declared by several kinds: {', '.join(sorted(files))}")
sys.exit(1 if clashes else 0)
