#!/usr/bin/env python3
"""Checks that the configuration and statistics headers compile without SystemC: preprocesses
each of them (g++ -M with the include flags the build gives src/run, from compile_commands.json)
and fails, naming the header and the SystemC or TLM-2.0 header it reaches, when one does.
Usage: check_systemc_free.py BUILD_DIR [SOURCE_DIR]"""
import json
import pathlib
import re
import shlex
import subprocess
import sys

build = pathlib.Path(sys.argv[1])
root = pathlib.Path(sys.argv[2] if len(sys.argv) > 2 else pathlib.Path(__file__).parent.parent)
src = root / "src"
# The headers a script, a configuration or a statistics reader may include (issue 26).
headers = sorted({src / "sim" / "rtu_config.h", *src.glob("config/*.h"), *src.rglob("*statistics*.h")})
systemc = re.compile(r"(^|/)(systemc|systemc\.h|tlm|tlm\.h)$|/(sysc|tlm_core|tlm_utils)/")

commands = json.loads((build / "compile_commands.json").read_text())
run = next(c for c in commands if pathlib.Path(c["file"]).parent == src / "run")
words = shlex.split(run["command"]) if "command" in run else list(run["arguments"])
flags = [words[0]]
skip = False
for word in words[1:]:
    if skip:
        skip = False
    elif word == "-o":
        skip = True
    elif word != "-c" and word != run["file"]:
        flags.append(word)

problems = []
for header in headers:
    result = subprocess.run(flags + ["-M", "-x", "c++", str(header)], cwd=run["directory"],
                            capture_output=True, text=True)
    name = header.relative_to(root)
    if result.returncode != 0:
        problems.append(f"{name}: does not preprocess:\n{result.stderr}")
        continue
    reached = [d for d in result.stdout.replace("\\\n", " ").split()[1:] if systemc.search(d)]
    if reached:
        problems.append(f"{name}: reaches {reached[0]}")
for problem in problems:
    print(problem)
print(f"{len(headers)} headers, {len(problems)} reach SystemC" if problems else
      f"{len(headers)} configuration and statistics headers compile without SystemC")
sys.exit(1 if problems else 0)
