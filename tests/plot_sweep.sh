#!/usr/bin/env bash
# Issue 31 section 1 on real runs: a 3x2 sweep of scheduler and L1 size on two scenes, plotted
# with --x/--y/--by/--facet (every series drawn), its best configuration and report; diff of two
# render runs; fps rows in full as JSON lines. Usage: plot_sweep.sh path/to/rtusim
set -euo pipefail
rtusim=$1
source "$(dirname "${BASH_SOURCE[0]}")/shell_test_helpers.sh"

"$rtusim" sweep --preset cached --depth 5 --width 64 --height 36 --cores 4 \
  --grid scheduler=cfa,fa,rr --grid memory.l1.size=2KiB,16KiB --grid scene=menger,terrain \
  --out s.csv -j 2 >/dev/null 2>&1
python3 -c "
import json, sys
rows = [json.loads(l) for l in open('s.jsonl')]
assert len(rows) == 12 and all(r['preset'] == 'cached' for r in rows), 'rows or preset'"

# Frame rate against the L1 size, a line per scheduler, a panel per scene: 3 lines in each of
# 2 panels.
"$rtusim" plot --x memory.l1.size --y fps --by scheduler --facet scene --out-dir p s.jsonl >/dev/null
[[ $(grep -c '<g id="series ' p/fps_vs_memory_l1_size.svg) == 6 ]] || fail "not 6 lines"
# The defaults: the frame rate against each varied key but the scene, a panel per scene.
"$rtusim" plot --out-dir d s.jsonl >/dev/null
[[ $(grep -c '<g id="series ' d/fps_vs_scheduler.svg) == 4 ]] || fail "fps against scheduler: not 2 L1 sizes x 2 panels"
[[ $(grep -c '<g id="series ' d/fps_vs_memory_l1_size.svg) == 6 ]] || fail "fps against L1: not 3 schedulers x 2 panels"
# --where keeps the rr rows alone: one line per panel.
"$rtusim" plot --x memory.l1.size --where scheduler=rr --out-dir w s.jsonl >/dev/null
[[ $(grep -c '<g id="series ' w/fps_vs_memory_l1_size.svg) == 2 ]] || fail "--where scheduler=rr"

# --pareto: the frame rate against the rows' block RAMs (a 2 KiB L1 2 RAMB18 a core, a 16 KiB one 8),
# with its front; no other plot.
"$rtusim" plot --pareto bram18k --where scene=menger --out-dir r s.jsonl >pareto.txt
[[ $(ls r) == $'pareto_fps_vs_bram18k.png\npareto_fps_vs_bram18k.svg' ]] || fail "plot --pareto: $(ls r)"
grep -q 'id="pareto front"' r/pareto_fps_vs_bram18k.svg || fail "plot --pareto drew no front"

# The best row per scene is the one with the highest fps, against the first row's configuration.
"$rtusim" best s.jsonl >best.txt
python3 - <<'PY'
import json, re
rows = [json.loads(l) for l in open("s.jsonl")]
text = open("best.txt").read()
for scene in ("menger", "terrain"):
    mine = [(r["statistics"]["fps"], i + 1) for i, r in enumerate(rows) if r["config"]["scene"] == scene]
    best = max(mine)
    line = next(l for l in text.splitlines() if l.startswith("scene " + scene))
    named = int(re.search(r"best #(\d+)", line).group(1))
    assert rows[named - 1]["statistics"]["fps"] == best[0], (line, best)
PY

"$rtusim" report s.jsonl --out r.html >/dev/null
grep -q '<table id="rows" class="sortable">' r.html || fail "report: no sortable table"
[[ $(grep -c '<tr class="best">' r.html) -ge 2 ]] || fail "report: no best row per scene"

# diff of two runs: the scheduler first, then the statistics.
"$rtusim" render --preset cached --scene menger --depth 5 --width 64 --height 36 --stats a.json >/dev/null
"$rtusim" render --preset cached --scene menger --depth 5 --width 64 --height 36 --scheduler fa \
  --stats b.json >/dev/null
"$rtusim" diff a.json b.json >diff.txt
[[ $(sed -n 3p diff.txt | tr -s ' ') == " scheduler cfa fa" ]] || fail "diff: $(head -5 diff.txt)"
grep -q "^  fps " diff.txt || fail "diff: no fps"
# Two sweeps: the key that differs between them first, rows paired.
"$rtusim" sweep --preset cached --depth 5 --width 64 --height 36 --cores 4 --set memory.dram.latency=40 \
  --grid scheduler=cfa,fa,rr --grid memory.l1.size=2KiB,16KiB --grid scene=menger,terrain \
  --out s40.csv -j 2 >/dev/null 2>&1
"$rtusim" diff --stat fps s.jsonl s40.jsonl >sweeps.txt
[[ $(sed -n 3p sweeps.txt | tr -s ' ') == " memory.dram.latency 20 cycles 40 cycles" ]] || fail "$(head sweeps.txt)"
[[ $(grep -c "^row .*(A #" sweeps.txt) == 12 ]] || fail "diff of sweeps: not 12 pairs"
"$rtusim" report s.jsonl s40.jsonl --label dram20 --label dram40 --out c.html >/dev/null
grep -q "Comparison of the inputs" c.html || fail "report of two sweeps: no comparison"

# fps writes its rows in full beside the CSV: the report's fixed configuration is filled.
"$rtusim" fps --preset cached --scene menger --depth 5 --resolutions 64x36 --cores 1,4 --csv f.csv -j 1 >/dev/null
"$rtusim" report f.jsonl --out f.html >/dev/null
grep -q "<tr><td>memory.kind</td><td>cached</td></tr>" f.html || fail "fps report: no fixed configuration"
echo "plot sweep: all checks passed"
