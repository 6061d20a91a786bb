#!/usr/bin/env bash
# Exploration end to end: config --dump round trip, sweep rows equal to single runs, fps rows
# equal to render, resume after a killed sweep, failed rows, plots.
# Usage: exploration_end_to_end.sh path/to/rtusim
set -euo pipefail
rtusim=$1
source "$(dirname "${BASH_SOURCE[0]}")/shell_test_helpers.sh"
# Debian's python3 (json only here; matplotlib for the plots).
python=/usr/bin/python3
[[ -x $python ]] || python=python3

# Statistics of two run files equal, but for the host's own time.
same_statistics() {
  "$python" - "$1" "$2" <<'PY'
import json, sys
def load(path):
    data = json.load(open(path)) if path.endswith(".json") else json.loads(open(path).read())
    data["statistics"].pop("simulation")
    return data["statistics"], data["config"]
a, b = load(sys.argv[1]), load(sys.argv[2])
sys.exit(0 if a == b else 1)
PY
}

"$rtusim" build --scene sphere --depth 6 --out sphere.svo >/dev/null
"$rtusim" jobs --width 16 --height 12 --out jobs.bin >/dev/null

# config --dump -> --config gives the same run as the settings it was dumped from.
"$rtusim" config --dump --preset cached --set cores=4 --l1-size 1KiB >c.toml
"$rtusim" replay --svo sphere.svo --jobs jobs.bin --out a.bin --preset cached --set cores=4 \
  --l1-size 1KiB --stats a.json >/dev/null
"$rtusim" replay --config c.toml --svo sphere.svo --jobs jobs.bin --out b.bin --stats b.json >/dev/null
same_statistics a.json b.json || fail "config --dump round trip changes the run"
grep -q '"memory.l1.size": "1KiB"' a.json || fail "stats JSON without the configuration"
grep -q '"version"' a.json || fail "stats JSON without the version"
expect_error "did you mean 'memory.l1.size'" "$rtusim" config --dump --set memory.l1.sise=4KiB
expect_error "cores: 0 is out of range 1 .. 1024" "$rtusim" sweep --grid cores=1,0 --out x.csv

# Sweep rows equal single runs of their configurations.
"$rtusim" sweep --scene sphere --depth 5 --width 24 --height 16 --memory cached \
  --grid cores=1,4 --grid memory.l1.size=512,2KiB -j 2 --out rows.csv >sweep.txt
[[ $(wc -l <rows.jsonl) -eq 4 && $(wc -l <rows.csv) -eq 5 ]] || fail "sweep row count"
head -1 rows.csv | grep -q '^model,lt.quantum,cores,scheduler,clock_mhz,' || fail "CSV header starts with the keys"
i=0
while read -r row; do
  i=$((i + 1))
  "$python" -c 'import json,sys; print(json.dumps(json.loads(sys.argv[1])["config"]))' "$row" >row$i.json
  echo "$row" >row$i.jsonl
  "$rtusim" render --config row$i.json --stats single$i.json >/dev/null
  same_statistics row$i.jsonl single$i.json || fail "sweep row $i differs from its single run"
done <rows.jsonl

# Sweep rows carry the resource estimate as the last columns (docs/comparison.md, "Resources").
# Block RAMs by hand: the L2 (128 KiB: 16,384 x 64 bits, 64 RAMB18; tags 256 sets x 8 ways x
# (18 + 1) = 256 x 152, 5) is 69; an L1 of 512 B (64 words) and its tags are LUT RAM, one of
# 2 KiB (256 x 64) 2 RAMB18 a core; the SVO stacks (11 frames) and result registers none.
"$python" - rows.csv <<'PY' || fail "sweep resource columns"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
header = list(rows[0])
assert header[-9:] == ["memory_bits", "bram_bits", "bram18k", "dsp48e", "multipliers", "adders",
                       "dividers", "comparators", "luts"], header[-9:]
expected = {("1", "512"): 69, ("4", "512"): 69, ("1", "2KiB"): 71, ("4", "2KiB"): 77}
got = {(r["cores"], r["memory.l1.size"]): int(r["bram18k"]) for r in rows}
assert got == expected, got
assert all(r["dsp48e"] == "0" and r["adders"] == str(3 * int(r["cores"])) for r in rows), rows
PY

# fps rows equal render's statistics for the same configuration.
"$rtusim" fps --scene sphere --depth 5 --resolutions 24x16,32x18 --cores 2,8 -j 2 --csv fps.csv >fps.txt
head -1 fps.csv | grep -q '^width,height,cores,rays,total_cycles,cycles_per_ray,frame_ms,fps,limit' \
  || fail "fps CSV columns"
[[ $(wc -l <fps.csv) -eq 5 ]] || fail "fps row count"
# The resource estimate's columns after the error column, as sweep's after its statistics: the
# caches of the default (ideal) memory are none, so the block RAMs grow with the cores' stacks.
"$python" - fps.csv <<'PY' || fail "fps resource columns"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
header = next(csv.reader(open(sys.argv[1])))
assert header[header.index("error") + 1] == "memory_bits", header
two, eight = (next(r for r in rows if r["cores"] == c and r["width"] == "24") for c in ("2", "8"))
assert int(eight["memory_bits"]) > int(two["memory_bits"]) > 0, (two["memory_bits"], eight["memory_bits"])
PY
"$rtusim" render --scene sphere --depth 5 --width 32 --height 18 --cores 8 --stats r.json >/dev/null
cycles=$("$python" -c 'import json; print(json.load(open("r.json"))["statistics"]["total_cycles"])')
grep -q "^32,18,8,576,$cycles," fps.csv || fail "fps row differs from render ($cycles cycles)"

# Sampled rows (docs/fidelity.md): the estimate inside its interval, the simulated share within
# the fraction, the same row from fps and sweep; a fraction too small is refused before running.
"$rtusim" fps --scene menger --depth 5 --memory cached --resolutions 160x120 --cores 4 \
  --sample 0.5 --csv sampled.csv >sampled.txt
"$python" - sampled.csv <<'PY' || fail "sampled fps row"
import csv, sys
row = next(csv.DictReader(open(sys.argv[1])))
assert row["answered_by"] == "sampled", row["answered_by"]
assert float(row["total_cycles_ci_low"]) <= float(row["total_cycles"]) <= float(row["total_cycles_ci_high"])
assert 0 < float(row["simulated_fraction"]) <= 0.5
PY
grep -q "sampled SystemC simulation" sampled.txt || fail "fps heading does not say sampled"
"$rtusim" sweep --scene menger --depth 5 --memory cached --width 160 --height 120 --cores 4 \
  --sample 0.5 --grid cores=4 --out sampled_sweep.csv -j 1 >/dev/null
sampledCycles=$("$python" -c 'import csv; print(next(csv.DictReader(open("sampled.csv")))["total_cycles"])')
grep -q ",$sampledCycles," sampled_sweep.csv || fail "sweep's sampled row differs from fps's"
if "$rtusim" fps --scene menger --depth 5 --memory cached --resolutions 160x120 --cores 4 \
  --sample 0.01 >small.txt 2>&1; then fail "a too small sample fraction ran"; fi
grep -q "sample.fraction 0.01" small.txt || fail "too small sample fraction not named"

# fidelity: every mode against the SystemC model; the exact modes exact, golden's results equal.
# Its sampled modes take --sample-seed at their own fractions: no "has no effect" warning.
"$rtusim" fidelity --scene menger --depth 5 --width 160 --height 120 --cores 4 --fractions 0.5 \
  --quanta 100,1000 --sample-seed 3 --csv fidelity.csv >fidelity.txt 2>fidelity.err
! grep -q "has no effect" fidelity.err || fail "fidelity warns that its sample seed has no effect"
"$python" - fidelity.csv <<'PY' || fail "fidelity rows"
import csv, sys
rows = {r["mode"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert list(rows) == ["systemc", "recurrence", "lt q100", "lt q1000", "sampled 0.5", "golden"], list(rows)
for lt in ("lt q100", "lt q1000"):
    assert rows[lt]["results_equal_golden"] == "yes" and abs(float(rows[lt]["total_cycles_error"])) < 0.05, rows[lt]
for exact in ("systemc", "recurrence"):
    assert float(rows[exact]["total_cycles_error"]) == 0 and float(rows[exact]["per_ray_error_p99"]) == 0
    assert rows[exact]["results_equal_golden"] == "yes"
sampled = rows["sampled 0.5"]
assert float(sampled["total_cycles_ci_low"]) <= float(sampled["total_cycles"]) <= float(sampled["total_cycles_ci_high"])
assert rows["golden"]["total_cycles"] == "" and rows["golden"]["results_equal_golden"] == "yes"
PY

# On a frame too small for the default sampled fractions, fidelity skips them with a note and
# measures the other modes; a fraction asked for on the command line is still refused.
"$rtusim" fidelity --scene menger --depth 3 --width 32 --height 24 --quanta 100 \
  --csv small_fidelity.csv >small_fidelity.txt || fail "fidelity on a small frame: $(cat small_fidelity.txt)"
test "$(grep -c "^note: the sampled mode at" small_fidelity.txt)" = 3 || fail "skipped fractions not noted"
! grep -q "^sampled" small_fidelity.csv || fail "a skipped fraction has a row"
grep -q "^golden" small_fidelity.csv || fail "golden row missing on a small frame"
! "$rtusim" fidelity --scene menger --depth 3 --width 32 --height 24 --quanta 100 --fractions 0.02 \
  >small_asked.txt 2>&1 || fail "a fraction too small, asked for, was not refused"
grep -q "sample.fraction 0.02" small_asked.txt || fail "the refused fraction is not named"

# --model: the loosely-timed and golden models answer fps and sweep rows, named in the CSV.
"$rtusim" sweep --scene menger --depth 5 --width 64 --height 48 --memory cached --model lt \
  --grid cores=4,16 --out lt_sweep.csv -j 1 >/dev/null
test "$(grep -c '^lt,.*,lt,' lt_sweep.csv)" = 2 || fail "sweep --model lt rows"
"$rtusim" render --scene menger --depth 5 --width 64 --height 48 --memory cached --model lt \
  --stats lt_stats.json >lt_render.txt
grep -q "estimated by the loosely-timed model" lt_render.txt || fail "render --model lt report"
grep -q '"model": "lt"' lt_stats.json || fail "render --model lt statistics JSON"
"$rtusim" fps --scene menger --depth 5 --resolutions 64x48 --cores 4 --model golden \
  --csv golden_fps.csv >golden_fps.txt
grep -q "golden costs in the recurrence" golden_fps.txt || fail "fps --model golden heading"
"$rtusim" fps --scene menger --depth 5 --resolutions 64x48 --cores 4 --model lt --sample 0.5 \
  >lt_sample.txt 2>&1 || true
grep -q "does not go with --model lt" lt_sample.txt || fail "--sample with --model lt not refused"

# A configuration that cannot run gets its error in its row; the sweep goes on (and exits
# non-zero).
if "$rtusim" sweep --scene sphere --depth 5 --width 8 --height 8 --memory cached \
  --grid memory.l1.size=16,1KiB --out bad.csv >bad.txt 2>&1; then
  fail "a sweep with an invalid row exited 0"
fi
grep -q '"status":"invalid"' bad.jsonl && grep -q 'do not hold one 32-byte line' bad.jsonl \
  || fail "failed row without its error"
grep -q '"status":"ok"' bad.jsonl || fail "the sweep stopped at a failed row"

# Resume: kill a sweep (and its workers) after its first row; the rerun completes it, each
# configuration once. How many rows the kill left depends on the machine's load, so the count
# of rows kept is checked below on a cut file instead.
grid=(--scene sphere --depth 6 --width 96 --height 64 --grid cores=1,2,3,4,5,6 -j 1 --out resume.csv)
setsid "$rtusim" sweep "${grid[@]}" >/dev/null 2>&1 &
leader=$!
for _ in $(seq 1 300); do
  [[ -s resume.jsonl ]] && break
  sleep 0.05
done
kill -KILL -- -"$leader" 2>/dev/null || true
wait "$leader" 2>/dev/null || true
[[ -s resume.jsonl ]] || fail "the killed sweep wrote no row"
first_row=$(head -1 resume.jsonl)
"$rtusim" sweep "${grid[@]}" >resume.txt
[[ $(wc -l <resume.jsonl) -eq 6 && $(head -1 resume.jsonl) == "$first_row" ]] || fail "resume rows"
one_run_each() {
  [[ $("$python" -c 'import json,sys; print(len({json.dumps(json.loads(l)["config"]) for l in open(sys.argv[1])}))' "$1") -eq 6 ]]
}
one_run_each resume.jsonl || fail "a configuration ran twice"

# A sweep cut after two rows and in the middle of the third keeps the two and reruns the rest.
head -2 resume.jsonl >cut.jsonl
# (Not `sed | head -c`: with pipefail, sed's later writes into the closed pipe fail the test.)
sed -n 3p resume.jsonl >third.jsonl
head -c 40 third.jsonl >>cut.jsonl
cp cut.jsonl resume.jsonl
"$rtusim" sweep "${grid[@]}" >resume.txt
grep -q "2 already done" resume.txt || fail "resume did not skip the two rows done"
[[ $(wc -l <resume.jsonl) -eq 6 && $(head -2 resume.jsonl) == "$(head -2 cut.jsonl)" ]] || fail "cut resume rows"
one_run_each resume.jsonl || fail "a configuration ran twice after the cut"

# Plots and the report from the rows.
if "$python" -c 'import matplotlib' 2>/dev/null; then
  "$rtusim" plot rows.jsonl --out-dir plots >/dev/null
  [[ -s plots/fps_vs_cores.png && -s plots/fps_vs_cores.svg ]] || fail "plots missing"
  # Sizes are written as "512" and "2KiB": the plot reads them as numbers.
  [[ -s plots/hit_rate_vs_l1_size.png ]] || fail "no hit-rate plot from an L1 size sweep"
  "$rtusim" report rows.jsonl --out report.html >/dev/null
  grep -q "<table" report.html || fail "report without its table"
fi
echo "exploration end-to-end: ok"
