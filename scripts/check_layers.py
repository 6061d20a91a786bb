#!/usr/bin/env python3
"""Checks that every #include in src/ points down the layer order of src/layers.txt, and that
only the folders marked `systemc` there include SystemC or TLM-2.0 headers. Prints each
offending include as file:line and exits 1; exits 0 when the tree follows the order."""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent)
src = root / "src"
layers, systemc = [], set()
for line in (src / "layers.txt").read_text().splitlines():
    words = line.split("#")[0].split()
    if words:
        layers.append(words[0])
        if "systemc" in words[1:]:
            systemc.add(words[0])


def layer_of(folder):
    """The layer index of a folder of src/ and the core kind it belongs to (None for none). A
    kind's folder `kinds/<kind>` sits at `kinds/*`; its plug-in folder `kinds/<kind>/<layer>`
    (`kinds/kd/explore`) sits at that layer, so the kind's code that needs a higher layer's types
    lives in the kind's folder."""
    if folder in layers:
        return layers.index(folder), None
    parts = folder.split("/")
    if len(parts) >= 2 and parts[0] + "/*" in layers:
        kind = parts[0] + "/" + parts[1]
        if len(parts) == 2:
            return layers.index(parts[0] + "/*"), kind
        plugin_layer = "/".join(parts[2:])
        if plugin_layer in layers and layers.index(plugin_layer) > layers.index(parts[0] + "/*"):
            return layers.index(plugin_layer), kind
    return None, None


include = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
systemc_header = re.compile(r"^(systemc|systemc\.h|tlm|tlm\.h|tlm_utils/.*|sysc/.*)$")
problems = []
for path in sorted(src.rglob("*")):
    if path.suffix not in (".h", ".cpp"):
        continue
    folder = path.parent.relative_to(src).as_posix()
    own, own_kind = layer_of(folder)
    if own is None:
        problems.append(f"{path.relative_to(root)}: folder {folder} is not in src/layers.txt")
        continue
    for number, line in enumerate(path.read_text().splitlines(), 1):
        match = include.match(line)
        if not match:
            continue
        where = f"{path.relative_to(root)}:{number}"
        name = match.group(2)
        if match.group(1) == "<":
            if systemc_header.match(name) and folder not in systemc:
                problems.append(f"{where}: <{name}> in {folder}, which is not a SystemC folder")
            continue
        target = src / name
        if not target.is_file():
            if "/" in name:
                problems.append(f'{where}: "{name}" is not a file under src/')
            continue  # a generated header (embedded presets, version) or a third-party one
        other = target.parent.relative_to(src).as_posix()
        theirs, their_kind = layer_of(other)
        if theirs is None or theirs > own:
            problems.append(f'{where}: {folder} includes "{name}" from {other}, above it')
        elif own_kind and their_kind and own_kind != their_kind:
            problems.append(f'{where}: kind {folder} includes "{name}" from kind {other}')
for problem in problems:
    print(problem)
sys.exit(1 if problems else 0)
