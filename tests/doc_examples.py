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
statistics files a.json, b.json and a replay's stats.json), are made there first, small.

EXEMPT lists the examples too long for the suite or needing what CI lacks, each with its reason;
they are only parsed (RTUSIM_PARSE_ONLY=1: options, values and required options checked, nothing
run; the scripts with `bash -n`). Where later examples read an exempt one's outputs (m.svo,
jobs.bin), a stand-in makes them: the same command at a small size. An exempt entry that matches
no example is an error, so the list cannot go stale. A command written twice runs once. A
failing example fails the test with its file:line.
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

# The examples only parsed, with the reason (as normalised: brackets left out), and where later
# examples read an exempt one's outputs, a stand-in: the same command at a small size, run instead.
PLOTS = "draws every figure with matplotlib, 8-10 s (tests/plot_sweep.sh runs plot and report)"
EXEMPT = {
    "./run.sh": ("installs packages, builds and renders the default scenes: the set-up itself",
                 None),
    "./test.sh": ("builds and runs the whole suite, this test included", None),
    "rtusim fps --preset thesis --resolutions 640x360,1280x720 --cores 1,4,16":
        ("six frames up to 1280x720: 6 s", None),
    "rtusim report l1.jsonl --out l1.html": (PLOTS, None),
    "rtusim build --scene menger --depth 10 --out m.svo":
        ("a depth-10 octree: 15-35 s", "rtusim build --scene menger --depth 6 --out m.svo"),
    "rtusim jobs --width 1280 --height 720 --out jobs.bin":
        ("its readers (golden, replay) would take 8-16 s each on 1280x720",
         "rtusim jobs --width 64 --height 36 --out jobs.bin"),
    "rtusim wave t.fst": ("opens GTKWave on a display (CI has neither; tests/fst_trace.sh checks "
                          "the error without one)", None),
    "rtusim animate --scene-file scenes/default.toml --out-dir anim":
        ("the default scene's frames: 16 s (tests/animate_end_to_end.sh animates)", None),
    "rtusim fps --preset thesis --cores 1,2,4,8,16 --csv f.csv":
        ("the thesis' resolutions at five core counts: about 100 s", None),
    "rtusim plot rows.jsonl": (PLOTS, None),
    "rtusim report rows.jsonl --out r.html": (PLOTS, None),
    "rtusim compare --scene-file scenes/default.toml --html c.html":
        ("every architecture on the default scene's models: minutes (tests/cli_compare.sh)", None),
    "rtusim fidelity --preset cached --scene menger --width 1280 --height 720 --quanta 1000 "
    "--fractions 0.05,0.1 --csv f.csv": ("a 1280x720 frame in every mode: minutes", None),
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
        ["build", "--scene", "sphere", "--depth", "5", "--out", "sphere.svo"],
        ["jobs", "--width", "32", "--height", "18", "--out", "sphere_jobs.bin"],
        ["replay", "--svo", "sphere.svo", "--jobs", "sphere_jobs.bin", "--out", "sphere_out.bin",
         "--stats", "stats.json"],
    ]
    for arguments in setup:
        done = subprocess.run([rtusim] + arguments, cwd=work, capture_output=True, text=True)
        if done.returncode != 0:
            sys.exit("doc_examples: making the inputs failed: rtusim %s\n%s"
                     % (" ".join(arguments), done.stderr))


def run(rtusim, source, work, command):
    """(passed, seconds, output) of one example, run or (when exempt) only parsed."""
    start = time.monotonic()
    if command not in EXEMPT:
        passed, output = execute(rtusim, work, command)
        return passed, time.monotonic() - start, output
    reason, stand_in = EXEMPT[command]
    if command.startswith("./"):
        passed, output = execute(rtusim, work, "bash -n " + os.path.join(source, command[2:]))
    else:
        passed, output = execute(rtusim, work, command, {"RTUSIM_PARSE_ONLY": "1"})
    if passed and stand_in:
        passed, output = execute(rtusim, work, stand_in)
    return passed, time.monotonic() - start, output


def execute(rtusim, work, command, environment=None):
    """(passed, last lines of output) of one command line, `rtusim` the binary under test."""
    words = shlex.split(command)
    if words[0] == "rtusim":
        words[0] = rtusim
    try:
        done = subprocess.run(words, cwd=work, env=dict(os.environ, **(environment or {})),
                              capture_output=True, text=True, timeout=TIMEOUT_SECONDS,
                              stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return False, "timed out after %d s" % TIMEOUT_SECONDS
    output = (done.stdout + done.stderr).strip().splitlines()
    return done.returncode == 0, "\n".join(output[-12:])


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
        seen = set()
        for where, command in found:
            if is_synopsis(command) or command in seen:
                continue  # a command written twice runs once, at its first place
            seen.add(command)
            passed, seconds, output = run(rtusim, source, work, command)
            note = "parsed only: " + EXEMPT[command][0] + "; " if command in EXEMPT else ""
            print("%-26s %6.2f s %s%s%s" % (where, seconds, "" if passed else "FAILED ", note,
                                           command))
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
