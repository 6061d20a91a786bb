#!/usr/bin/env python3
"""Runs every example command of the README and the user guide as written.

usage: doc_examples.py RTUSIM SOURCE_DIR [--list]

The commands are taken from the documents themselves, so a new or changed example is tested
without editing this file:
- each line of a fenced code block (no language, or sh/bash/console) that starts with `rtusim`,
  `build/rtusim` or `./` (a trailing `# comment` dropped);
- each inline code span that is a command line: `rtusim` (or `build/rtusim`), a subcommand and at
  least one argument (the README's command table, and spans in the text such as
  `rtusim wave t.fst`).
Optional parts in brackets (`[--root A]`, `[-j N]`) are left out: the example runs in its plain
form. A span with `...` or an upper-case placeholder (`FILE`, `A`) is a synopsis of options, not
an example, and is not run (listed with --list).

The examples run in document order (README first) in one temporary working directory, so that
one example's outputs are the next one's inputs (m.svo, jobs.bin, rows.jsonl), with `rtusim`
replaced by the binary under test and `scenes/` linked from the source tree (the examples are
written to run from the repository's root). The inputs the examples take from the user, which no
example makes (a mesh f.obj, bunny.off and dragon.off, a Tray Racer scene file bunny.scene, the
statistics files a.json, b.json and stats.json), are made there first, small.

EXEMPT lists the examples too long for the suite or needing what CI lacks, each with its reason;
they are only parsed (RTUSIM_PARSE_ONLY=1: options, values and required options checked, nothing
run; the scripts with `bash -n`). An exempt entry that matches no example is an error, so the
list cannot go stale. A failing example fails the test with its file:line.
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

DOCUMENTS = ["README.md", "docs/user-guide.md"]

# The examples only parsed, with the reason (as normalised: brackets left out).
EXEMPT = {
    "./run.sh": "installs packages, builds and renders the default scenes: the set-up itself",
    "./test.sh": "builds and runs the whole suite, this test included",
    "rtusim wave t.fst": "opens GTKWave on a display (CI has neither; tests/fst_trace.sh checks "
                         "the error without one)",
    "rtusim fidelity --preset cached --scene menger --width 1280 --height 720 --quanta 1000 "
    "--fractions 0.05,0.1 --csv f.csv": "a 1280x720 frame in every mode: minutes",
}

SHELL_LANGUAGES = {"", "sh", "bash", "console", "shell"}
TIMEOUT_SECONDS = 120


def is_command_span(text):
    return re.match(r"^(build/)?rtusim [a-z][a-z-]* +\S", text) is not None


def examples(path, name):
    """(file:line, command) of each example in the markdown file `path`."""
    found, fence = [], None
    for number, line in enumerate(open(path, encoding="utf-8"), 1):
        stripped = line.strip()
        if stripped.startswith("```"):
            fence = None if fence is not None else stripped[3:].strip()
            continue
        where = "%s:%d" % (name, number)
        if fence is not None:
            command = re.sub(r"^\$ ", "", stripped)
            if fence in SHELL_LANGUAGES and re.match(r"^(build/rtusim|rtusim|\./)", command):
                found.append((where, re.sub(r"\s+#.*$", "", command)))
            continue
        for span in re.findall(r"`([^`]+)`", line):
            if is_command_span(span):
                found.append((where, span))
    return found


def normalise(command):
    """The example's plain form: no optional parts, table escapes undone, one space apart."""
    command = command.replace("\\|", "|")
    while re.search(r"\[[^\[\]]*\]", command):
        command = re.sub(r"\s*\[[^\[\]]*\]", "", command)
    command = re.sub(r"^build/rtusim\b", "rtusim", command)
    return " ".join(command.split())


def is_synopsis(command):
    return "..." in command or any(re.fullmatch(r"[A-Z]+", word) for word in command.split())


def make_inputs(rtusim, work):
    """The files the examples take from the user: small, made here."""
    octahedron = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
    faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    scaled = [tuple(0.8 * c for c in v) for v in octahedron]
    with open(os.path.join(work, "f.obj"), "w") as obj:
        obj.writelines("v %g %g %g\n" % v for v in scaled)
        obj.writelines("f %d %d %d\n" % tuple(i + 1 for i in f) for f in faces)
    for name in ("bunny.off", "dragon.off"):
        with open(os.path.join(work, name), "w") as off:
            off.write("OFF\n%d %d 0\n" % (len(scaled), len(faces)))
            off.writelines("%g %g %g\n" % v for v in scaled)
            off.writelines("3 %d %d %d\n" % f for f in faces)
    small = ["--scene", "sphere", "--depth", "5", "--width", "32", "--height", "18"]
    setup = [
        ["build", "--accel", "kdtree", "--mesh", "bunny.off", "--out", "bunny.kd",
         "--trayracer-scene", "bunny.scene"],
        ["render"] + small + ["--cores", "2", "--stats", "a.json"],
        ["render"] + small + ["--cores", "4", "--stats", "b.json"],
        ["render"] + small + ["--stats", "stats.json"],
    ]
    for arguments in setup:
        done = subprocess.run([rtusim] + arguments, cwd=work, capture_output=True, text=True)
        if done.returncode != 0:
            sys.exit("doc_examples: making the inputs failed: rtusim %s\n%s"
                     % (" ".join(arguments), done.stderr))


def run(rtusim, source, work, command):
    """(passed, seconds, output) of one example, run or (when exempt) only parsed."""
    words = shlex.split(command)
    environment = dict(os.environ)
    if command in EXEMPT:
        if words[0].startswith("./"):
            words = ["bash", "-n", os.path.join(source, words[0])]
        environment["RTUSIM_PARSE_ONLY"] = "1"
    if words[0] == "rtusim":
        words[0] = rtusim
    start = time.monotonic()
    try:
        done = subprocess.run(words, cwd=work, env=environment, capture_output=True, text=True,
                              timeout=TIMEOUT_SECONDS, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return False, time.monotonic() - start, "timed out after %d s" % TIMEOUT_SECONDS
    output = (done.stdout + done.stderr).strip().splitlines()
    return done.returncode == 0, time.monotonic() - start, "\n".join(output[-12:])


def main():
    rtusim, source = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    found = []
    for name in DOCUMENTS:
        found += [(where, normalise(c)) for where, c in examples(os.path.join(source, name), name)]
    if "--list" in sys.argv:
        for where, command in found:
            kind = "synopsis" if is_synopsis(command) else "exempt" if command in EXEMPT else "run"
            print("%-26s %-8s %s" % (where, kind, command))
        return
    stale = set(EXEMPT) - {command for _, command in found}
    if stale:
        sys.exit("doc_examples: exempt but in no document: %s" % "; ".join(sorted(stale)))
    work = tempfile.mkdtemp(prefix="rtusim-examples-")
    failures = []
    try:
        os.symlink(os.path.join(source, "scenes"), os.path.join(work, "scenes"))
        make_inputs(rtusim, work)
        for where, command in found:
            if is_synopsis(command):
                continue
            passed, seconds, output = run(rtusim, source, work, command)
            print("%-26s %6.2f s %s%s" % (where, seconds, "" if passed else "FAILED ", command))
            if not passed:
                failures.append("%s: %s\n%s" % (where, command, output))
    finally:
        shutil.rmtree(work)
    if failures:
        print("\n".join(["", "doc_examples: %d example(s) failed:" % len(failures)] + failures))
        sys.exit(1)
    print("doc_examples: ok")


if __name__ == "__main__":
    main()
