#!/usr/bin/env python3
"""Mutation fuzzing of every file rtusim reads, and the check of malformed-file directories.

fuzz:   fuzz_inputs.py RTUSIM --mutants N [--formats ply,obj] [--seed S] [--save CORPUS_DIR]
        Writes N mutants per format from valid seed files (made by rtusim itself or written
        here), runs every command that reads the format on each, and counts the outcomes:
        accepted (exit 0), rejected (non-zero exit, message naming the file) and the failures:
        crash (a signal), hang (past the time limit), unclear (non-zero exit without the file's
        name). Failing mutants are copied to CORPUS_DIR/<format>/. Exit status 1 on any failure.
check:  fuzz_inputs.py RTUSIM --check DIR [DIR...]
        Every file in DIR/<format>/ must be rejected by every command that reads the format:
        non-zero exit, message naming the file, within the time limit, never a signal.
"""
import argparse
import hashlib
import os
import random
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time

# A mesh loader child is killed after this long (RTUSIM_MESH_SECONDS); a run past the harness'
# limit is a hang.
MESH_SECONDS = "3"
TIME_LIMIT_SECONDS = 15  # --time-limit

INTERESTING_NUMBERS = ["0", "-1", "1", "255", "256", "65535", "4294967295", "4294967296",
                       "2147483648", "-2147483649", "18446744073709551615",
                       "99999999999999999999999", "1e308", "-1e308", "1e-320", "nan", "inf", "-0",
                       "0x10", "1.5", ""]
INTERESTING_WORDS = [0, 1, 0xFFFFFFFF, 0x80000000, 0x7FFFFFFF, 0xFFFF, 0x10000, 0x7F800000,
                     0xFF800000, 0x7FC00000]


# A small animated scene (docs/scenes.md): two instances of a procedural ball, one moving.
SCENE = b"""width = 8
height = 6
frames = 2
frame_rate = 4

[models.ball]
procedural = "sphere"
depth = 3

[[instances]]
model = "ball"
colour = [0.8, 0.3, 0.2]
keys = [{ time = 0, translation = [-0.6, 0, 0], scale = 0.5 }]

[[instances]]
model = "ball"
keys = [
  { time = 0, translation = [0.6, 0, 1], rotation_deg = [0, 30, 0] },
  { time = 1, translation = [0.6, 0.5, 0], scale = [1, 0.5, 1] },
]

[camera]
keys = [{ time = 0, position = [0, 0.5, -4], look_at = [0, 0, 0] }]
"""


class Format:
    """A file format: its extension, whether it is text, and the rtusim commands that read it
    ({file} is the input, {dir} the scratch directory with the seed files of other formats).
    `check_commands` read it too but take long on a valid file: only malformed files (--check)
    are given to them."""

    def __init__(self, name, extension, text, commands, check_commands=()):
        self.name, self.extension, self.text = name, extension, text
        self.commands, self.check_commands = commands, list(check_commands)


FORMATS = {f.name: f for f in [
    Format("svo", "svo", False, [
        ["validate", "{file}"],
        ["golden", "--svo", "{file}", "--jobs", "{dir}/seed.jobs", "--out", "{dir}/out.bin"],
        ["replay", "--svo", "{file}", "--jobs", "{dir}/seed.jobs", "--out", "{dir}/out.bin",
         "--cores", "2"],
        ["render", "--svo", "{file}", "--width", "8", "--height", "6", "--cores", "2"],
        ["accuracy", "--svo", "{file}", "--width", "8", "--height", "6"],
    ], check_commands=[["fps", "--svo", "{file}"]]),
    Format("jobs", "jobs", False, [
        ["golden", "--svo", "{dir}/seed.svo", "--jobs", "{file}", "--out", "{dir}/out.bin"],
        ["replay", "--svo", "{dir}/seed.svo", "--jobs", "{file}", "--out", "{dir}/out.bin",
         "--cores", "2"],
    ]),
    Format("rays", "rays", False, [
        ["golden", "--svo", "{dir}/model.svo", "--rays", "{file}", "--out", "{dir}/out.bin"],
        ["replay", "--svo", "{dir}/model.svo", "--rays", "{file}", "--out", "{dir}/out.bin",
         "--cores", "2"],
    ]),
    Format("binvox", "binvox", False, [
        ["build", "--binvox", "{file}", "--out", "{dir}/out.svo"],
        ["render", "--binvox", "{file}", "--width", "8", "--height", "6", "--cores", "2"],
        ["accuracy", "--binvox", "{file}", "--width", "8", "--height", "6"],
    ]),
    Format("obj", "obj", True, [
        ["build", "--mesh", "{file}", "--depth", "5", "--out", "{dir}/out.svo"],
        ["render", "--mesh", "{file}", "--depth", "5", "--width", "8", "--height", "6",
         "--cores", "2"],
        ["accuracy", "--mesh", "{file}", "--depth", "5", "--width", "8", "--height", "6"],
    ]),
    Format("ply", "ply", False, [
        ["build", "--mesh", "{file}", "--depth", "5", "--out", "{dir}/out.svo"],
        ["render", "--mesh", "{file}", "--depth", "5", "--width", "8", "--height", "6",
         "--cores", "2"],
        ["accuracy", "--mesh", "{file}", "--depth", "5", "--width", "8", "--height", "6"],
    ]),
    Format("toml", "toml", True, [
        ["config", "--dump", "--config", "{file}"],
        ["golden", "--config", "{file}", "--svo", "{dir}/seed.svo", "--jobs", "{dir}/seed.jobs",
         "--out", "{dir}/out.bin"],
    ]),
    Format("json", "json", True, [
        ["config", "--dump", "--config", "{file}"],
        ["golden", "--config", "{file}", "--svo", "{dir}/seed.svo", "--jobs", "{dir}/seed.jobs",
         "--out", "{dir}/out.bin"],
    ]),
    Format("scene", "toml", True, [
        ["animate", "--scene-file", "{file}", "--frames", "1", "--width", "8", "--height", "6",
         "--out-dir", "{dir}/animation", "--cache-dir", "{dir}/models", "--threads", "1"],
        ["animate", "--scene-file", "{file}", "--frames", "1", "--width", "8", "--height", "6",
         "--out-dir", "{dir}/animation", "--cache-dir", "{dir}/models", "--model", "ca",
         "--cores", "2"],
    ]),
    Format("sweep", "toml", True, [
        ["sweep", "--sweep-file", "{file}", "--out", "{dir}/out", "--slurm", "--dry-run",
         "--sweep-dir", "{dir}/sweep"],
    ]),
]}


class Runner:
    """Runs rtusim commands on one input file each, in a scratch directory of seed files."""

    def __init__(self, rtusim, scratch, time_limit):
        self.rtusim, self.scratch, self.time_limit = rtusim, scratch, time_limit
        self.env = dict(os.environ, RTUSIM_MESH_SECONDS=MESH_SECONDS)

    def output(self, arguments):
        result = subprocess.run([self.rtusim] + arguments, capture_output=True, env=self.env,
                                check=True)
        return result.stdout.decode()

    def outcome(self, command, path):
        """'accepted', 'rejected', 'crash', 'hang' or 'unclear', and the error output."""
        arguments = [a.format(file=path, dir=self.scratch) for a in command]
        try:
            result = subprocess.run([self.rtusim] + arguments, stdin=subprocess.DEVNULL,
                                    stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                    timeout=self.time_limit, env=self.env)
        except subprocess.TimeoutExpired:
            return "hang", ""
        message = result.stderr.decode(errors="replace")
        if result.returncode < 0 or result.returncode > 128:
            return "crash", message
        if result.returncode == 0:
            return "accepted", message
        return ("rejected" if path in message else "unclear"), message


# ---- seed files ---------------------------------------------------------------------------

CUBE_OBJ = """# unit cube
v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1
f 1 2 3 4\nf 5 8 7 6\nf 1 5 6 2\nf 2 6 7 3\nf 3 7 8 4\nf 5 1 4 8
"""
TETRAHEDRON = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRAHEDRON_FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def ply_header(format_name):
    return ("ply\nformat %s 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
            "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
            "end_header\n" % format_name).encode()


def ascii_ply():
    body = "".join("%g %g %g\n" % v for v in TETRAHEDRON)
    body += "".join("3 %d %d %d\n" % f for f in TETRAHEDRON_FACES)
    return ply_header("ascii") + body.encode()


def binary_ply():
    body = b"".join(struct.pack("<3f", *v) for v in TETRAHEDRON)
    body += b"".join(struct.pack("<B3i", 3, *f) for f in TETRAHEDRON_FACES)
    return ply_header("binary_little_endian") + body


def binvox(dim):
    voxels = dim ** 3
    runs, solid = bytearray(), voxels // 2
    for value, count in ((1, solid), (0, voxels - solid)):
        while count > 0:
            runs += bytes([value, min(count, 255)])
            count -= min(count, 255)
    return b"#binvox 1\ndim %d %d %d\ntranslate 0 0 0\nscale 1\ndata\n" % (dim, dim, dim) + runs


SWEEP = b"""[grid]
cores = [1, 2]
'memory.l1.size' = ['1KiB', '4KiB']

[[configs]]
'memory.kind' = 'cached'
'memory.dram.latency' = 40
"""
CONFIG_JSON = b'{"cores": 4, "memory": {"kind": "cached", "l1": {"size": "2KiB"}}, "stack_frames": 12}\n'


def write_seeds(runner):
    """Seed files per format in `scratch`, also used as the other inputs of the commands."""
    def made(name, arguments):
        runner.output(arguments)
        return open(os.path.join(runner.scratch, name), "rb").read()

    address = re.search(r"model header at word (\d+)", runner.output([
        "build", "--scene", "sphere", "--depth", "4", "--model-header",
        "--out", os.path.join(runner.scratch, "model.svo")])).group(1)
    seeds = {
        "svo": [made("seed.svo", ["build", "--scene", "menger", "--depth", "3",
                                  "--out", os.path.join(runner.scratch, "seed.svo")])],
        "jobs": [made("seed.jobs", ["jobs", "--width", "8", "--height", "6",
                                    "--out", os.path.join(runner.scratch, "seed.jobs")])],
        "rays": [made("seed.rays", ["jobs", "--width", "8", "--height", "6", "--rays",
                                    os.path.join(runner.scratch, "seed.rays"),
                                    "--model-address", address])],
        "binvox": [binvox(4), binvox(5)],
        "obj": [CUBE_OBJ.encode()],
        "ply": [ascii_ply(), binary_ply()],
        "toml": [runner.output(["config", "--dump", "--preset", "cached"]).encode()],
        "json": [CONFIG_JSON],
        "sweep": [SWEEP],
        "scene": [SCENE],
    }
    return seeds


# ---- mutations ----------------------------------------------------------------------------

def flip_bits(data, rng):
    data = bytearray(data)
    for _ in range(rng.randint(1, 8)):
        position = rng.randrange(len(data))
        data[position] ^= 1 << rng.randrange(8)
    return bytes(data)


def overwrite_bytes(data, rng):
    data = bytearray(data)
    position = rng.randrange(len(data))
    data[position] = rng.choice([0x00, 0xFF, 0x7F, 0x80, 0x0A, 0x20])
    return bytes(data)


def splice(data, rng):
    start = rng.randrange(len(data))
    end = min(len(data), start + rng.randint(1, 64))
    if rng.random() < 0.5:
        return data[:start] + data[end:]  # delete a chunk
    return data[:start] + data[start:end] * rng.randint(2, 50) + data[end:]  # repeat it


def truncate(data, rng):
    return data[:rng.randrange(len(data))]


def replace_word(data, rng):
    if len(data) < 4:
        return data
    position = rng.randrange(len(data) // 4) * 4
    return data[:position] + struct.pack("<I", rng.choice(INTERESTING_WORDS)) + data[position + 4:]


NUMBER = re.compile(rb"-?\d+(\.\d+)?(e-?\d+)?")


def replace_number(data, rng):
    numbers = list(NUMBER.finditer(data))
    if not numbers:
        return data
    match = rng.choice(numbers)
    return data[:match.start()] + rng.choice(INTERESTING_NUMBERS).encode() + data[match.end():]


def shuffle_lines(data, rng):
    lines = data.split(b"\n")
    i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
    choice = rng.random()
    if choice < 0.4:
        lines[i], lines[j] = lines[j], lines[i]
    elif choice < 0.7:
        del lines[i]
    else:
        lines.insert(i, lines[j])
    return b"\n".join(lines)


def deep_nesting(data, rng):
    """A number wrapped in hundreds to tens of thousands of brackets or braces (issue 33: a JSON
    configuration 20,000 deep overflowed the stack)."""
    numbers = list(NUMBER.finditer(data))
    if not numbers:
        return data
    match = rng.choice(numbers)
    depth = rng.choice([100, 1000, 20000])
    opening, closing = rng.choice([(b"[", b"]"), (b"{a=", b"}"), (b'{"a":', b"}")])
    return (data[:match.start()] + opening * depth + match.group() + closing * depth +
            data[match.end():])


ELEMENT_COUNT = re.compile(rb"(element \w+ )(\d+)")


def count_mismatch(data, rng):
    """A PLY element count off by a few from the data (issue 33: more vertices declared than
    held read the faces as vertices, silently another model)."""
    counts = list(ELEMENT_COUNT.finditer(data))
    if not counts:
        return data
    match = rng.choice(counts)
    count = max(0, int(match.group(2)) + rng.choice([-2, -1, 1, 2]))
    return data[:match.start(2)] + str(count).encode() + data[match.end(2):]


BINARY_MUTATIONS = [flip_bits, overwrite_bytes, splice, truncate, replace_word, replace_number,
                    count_mismatch]
TEXT_MUTATIONS = [flip_bits, overwrite_bytes, splice, truncate, replace_number, replace_number,
                  shuffle_lines, shuffle_lines, deep_nesting]


def special_files(scratch):
    """Paths that are no regular file, given as any input (issue 33: a FIFO blocked forever,
    /dev/zero grew without end, a directory was "9223372036854775807 bytes")."""
    fifo, directory = os.path.join(scratch, "special.fifo"), os.path.join(scratch, "special.dir")
    if not os.path.exists(fifo):
        os.mkfifo(fifo)
        os.mkdir(directory)
    return [fifo, directory, "/dev/zero", "/dev/urandom"]


def check_special_files(runner, names):
    """Every command of every format must refuse each special file by name; the failures."""
    failures = 0
    for name in names:
        for path in special_files(runner.scratch):
            for command in FORMATS[name].commands + FORMATS[name].check_commands:
                outcome, message = runner.outcome(command, path)
                if outcome != "rejected":
                    failures += 1
                    print("FAIL special file %s as %s: rtusim %s: %s %s" % (
                        path, name, command[0], outcome, message.strip()[-300:]))
    return failures


def mutate(seed, text, rng):
    data = seed
    for _ in range(rng.randint(1, 3)):
        if data:
            data = rng.choice(TEXT_MUTATIONS if text else BINARY_MUTATIONS)(data, rng)
    return data


# ---- the two modes ------------------------------------------------------------------------

def require_seeds_accepted(runner, seeds):
    """A seed every command rejects would make its mutants' rejections meaningless."""
    for name, files in seeds.items():
        fmt = FORMATS[name]
        for index, data in enumerate(files):
            path = os.path.join(runner.scratch, "seed-%s-%d.%s" % (name, index, fmt.extension))
            with open(path, "wb") as file:
                file.write(data)
            for command in fmt.commands:
                outcome, message = runner.outcome(command, path)
                if outcome != "accepted":
                    sys.exit("seed %s: rtusim %s: %s %s" % (path, command[0], outcome, message))


def fuzz(args, runner):
    seeds = write_seeds(runner)
    require_seeds_accepted(runner, seeds)
    rng = random.Random(args.seed)
    counts, failures = {}, 0
    for name in args.formats.split(","):
        fmt = FORMATS[name]
        tally = counts.setdefault(name, {})
        start = time.monotonic()
        for index in range(args.mutants):
            data = mutate(rng.choice(seeds[name]), fmt.text, rng)
            path = os.path.join(runner.scratch, "mutant-%s-%d.%s" % (name, index, fmt.extension))
            with open(path, "wb") as file:
                file.write(data)
            for command in fmt.commands:
                outcome, message = runner.outcome(command, path)
                tally[outcome] = tally.get(outcome, 0) + 1
                if outcome in ("crash", "hang", "unclear"):
                    failures += 1
                    print("%s: %s on rtusim %s: %s" % (outcome, path, command[0],
                                                       message.strip()[-300:]))
                    save(args.save, name, fmt, data)
            os.remove(path)
        tally["seconds"] = round(time.monotonic() - start, 1)
        print("%-7s %4d mutants  %s" % (name, args.mutants, tally), flush=True)
    return failures + check_special_files(runner, args.formats.split(","))


def save(corpus, name, fmt, data):
    if not corpus:
        return
    directory = os.path.join(corpus, name)
    os.makedirs(directory, exist_ok=True)
    digest = hashlib.sha1(data).hexdigest()[:12]
    with open(os.path.join(directory, "%s.%s" % (digest, fmt.extension)), "wb") as file:
        file.write(data)


def check(args, runner):
    write_seeds(runner)
    failures, files, durations = 0, 0, []
    for root in args.check:
        for name in sorted(os.listdir(root)):
            if name not in FORMATS:
                sys.exit("%s: no format '%s' (formats: %s)" % (root, name, ", ".join(FORMATS)))
            for entry in sorted(os.listdir(os.path.join(root, name))):
                path = os.path.abspath(os.path.join(root, name, entry))
                files += 1
                for command in FORMATS[name].commands + FORMATS[name].check_commands:
                    start = time.monotonic()
                    outcome, message = runner.outcome(command, path)
                    seconds = time.monotonic() - start
                    durations.append(seconds)
                    if outcome != "rejected":
                        failures += 1
                        print("FAIL %s: rtusim %s: %s (%.1f s) %s" % (
                            path, command[0], outcome, seconds, message.strip()[-300:]))
    failures += check_special_files(runner, FORMATS)
    print("%d files, %d runs, %d failures; seconds per run: mean %.3f, slowest %.3f" % (
        files, len(durations), failures, sum(durations) / max(1, len(durations)),
        max(durations, default=0)))
    return failures if files else 1  # an empty directory checks nothing


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("rtusim")
    parser.add_argument("--mutants", type=int, default=50, help="mutants per format")
    parser.add_argument("--formats", default=",".join(FORMATS))
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--save", help="copy failing mutants to SAVE/<format>/")
    parser.add_argument("--time-limit", type=float, default=TIME_LIMIT_SECONDS,
                        help="seconds after which a run counts as a hang")
    parser.add_argument("--check", nargs="+", help="directories of malformed files by format")
    args = parser.parse_args()
    scratch = tempfile.mkdtemp(prefix="rtusim-fuzz-")
    runner = Runner(os.path.abspath(args.rtusim), scratch, args.time_limit)
    try:
        failures = check(args, runner) if args.check else fuzz(args, runner)
    finally:
        shutil.rmtree(scratch)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
