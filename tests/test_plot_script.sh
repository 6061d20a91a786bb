#!/usr/bin/env bash
# The sweep plot script: plots (PNG and SVG) and an HTML report from a small JSON-lines sweep, and
# clear errors with a non-zero exit for malformed input. Usage: test_plot_script.sh path/to/rtusim_plot.py
set -euo pipefail
script=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
source "$(dirname "${BASH_SOURCE[0]}")/shell_test_helpers.sh"
magic() {  # magic FILE HEX: FILE starts with the bytes HEX
  [[ -s $1 ]] || fail "$1 missing or empty"
  [[ $(head -c $((${#2} / 2)) "$1" | od -An -tx1 | tr -d ' \n') == "$2" ]] || fail "$1 is not the expected format"
}

# cores x resolution on cached memory with two DRAM latencies, one failed row.
python3 - <<'EOF'
import json
rows = []
for latency in (20, 80):
    for width, height in ((64, 36), (128, 72)):
        for cores in (1, 2, 4):
            config = {"cores": cores, "scheduler": "cfa", "clock_mhz": 100.0,
                      "memory.kind": "cached", "memory.l1.size": 4096, "memory.l2.size": 131072,
                      "memory.dram.latency": latency, "width": width, "height": height,
                      "scene": "sphere"}
            rays = width * height
            cycles = rays * (20 + latency // 10) // cores
            per_core = [{"core": i, "jobs": rays // cores, "busy": cycles // 2,
                         "blocked": cycles // 4, "handover": cycles // 20,
                         "idle": cycles - cycles // 2 - cycles // 4 - cycles // 20}
                        for i in range(cores)]
            stats = {"rays": rays, "total_cycles": cycles, "cycles_per_ray": cycles / rays,
                     "frame_ms": cycles / 1e5, "fps": 1e8 / cycles, "limit": "memory",
                     "core_time": {"busy": 0.5, "blocked": 0.25, "handover": 0.05, "idle": 0.2},
                     "cores": per_core,
                     "scheduler": {"policy": "cfa", "wait_histogram": [rays // 2, rays // 8, 3, 1][:cores + 1],
                                   "max_wait": cores},
                     "memory": {"kind": "cached", "l1": {"hit_rate": 0.9}, "l2": {"hit_rate": 0.6},
                                "dram": {"bytes": rays * 8, "bytes_per_cycle": 1.5}}}
            rows.append({"status": "ok", "error": "", "config": config, "statistics": stats})
rows.append({"status": "failed", "error": "--cores: too many cores for the test",
             "config": dict(rows[0]["config"], cores=8)})
with open("sweep.jsonl", "w") as f:
    f.write("\n".join(json.dumps(r) for r in rows) + "\n")
EOF

python3 "$script" plot --out-dir plots sweep.jsonl >plot.txt || fail "plot exit status"
for name in fps_vs_cores core_time wait_histogram cycles_per_ray_vs_dram_latency; do
  magic "plots/$name.png" 89504e470d0a1a0a
  grep -q "<svg" "plots/$name.svg" || fail "plots/$name.svg is not SVG"
  grep -q "plots/$name.png" plot.txt || fail "plot did not print plots/$name.png"
done
# Plots are written whole: beside their place, then renamed over it (a new file, not the old one
# rewritten in place), with no temporary left behind.
before=$(stat -c %i plots/fps_vs_cores.png)
python3 "$script" plot --out-dir plots sweep.jsonl >/dev/null || fail "plot over an existing plot"
[[ $(stat -c %i plots/fps_vs_cores.png) != "$before" ]] || fail "plots/fps_vs_cores.png rewritten in place"
[[ -z $(find plots -name '.*.tmp') ]] || fail "temporaries left in plots: $(find plots -name '.*.tmp')"
# The L1 size does not vary: no hit-rate plot.
[[ ! -e plots/hit_rate_vs_l1_size.png ]] || fail "hit-rate plot without a cache size sweep"

python3 "$script" report --out report.html sweep.jsonl >/dev/null || fail "report exit status"
[[ -s report.html ]] || fail "report.html missing"
grep -q '<table id="rows"' report.html || fail "report has no rows table"
grep -q 'src="data:image/svg+xml;base64,' report.html || fail "report has no embedded image"
grep -q "too many cores for the test" report.html || fail "report does not list the failed row"
grep -q "memory.dram.latency" report.html || fail "report does not name the varied keys"

# The fps CSV works too.
printf 'width,height,cores,rays,total_cycles,cycles_per_ray,frame_ms,fps,limit\n%s\n%s\n' \
  "64,36,1,2304,46080,20,0.46,2170,cores" "64,36,4,2304,11520,5,0.12,8680,cores" >fps.csv
python3 "$script" plot --out-dir csvplots fps.csv >/dev/null || fail "plot of an fps CSV"
magic csvplots/fps_vs_cores.png 89504e470d0a1a0a

# Malformed or missing input: a message and a non-zero exit.
printf '{"status":"ok","config":{"cores":1},"statistics":{}}\n{not json\n' >bad.jsonl
expect_error "bad.jsonl:2" python3 "$script" plot --out-dir bad bad.jsonl
expect_error "no such file" python3 "$script" report --out bad.html missing.jsonl
printf 'a,b\n1,2\n' >bad.csv
expect_error "CSV header" python3 "$script" plot --out-dir bad bad.csv
# --x/--y/--by/--facet: frame rate against cores, a line per resolution, a panel per DRAM
# latency: 2 resolutions in each of 2 panels, 4 lines in the SVG (each line is a group "series N").
python3 "$script" plot --x cores --y fps --by resolution --facet memory.dram.latency \
  --out-dir chosen sweep.jsonl >/dev/null || fail "plot --x --y --by --facet"
[[ $(grep -c '<g id="series ' chosen/fps_vs_cores.svg) == 4 ]] \
  || fail "plot --by resolution --facet latency: $(grep -c '<g id="series ' chosen/fps_vs_cores.svg) lines, not 4"
[[ $(ls chosen) == $'fps_vs_cores.png\nfps_vs_cores.svg' ]] || fail "plot --x drew other plots: $(ls chosen)"
# Any statistic on y, by its stats --list name.
python3 "$script" plot --x cores --y memory/dram/bytes --out-dir dram sweep.jsonl >/dev/null \
  || fail "plot --y memory/dram/bytes"
magic dram/memory_dram_bytes_vs_cores.png 89504e470d0a1a0a

# Nothing dropped: 2 core counts x 3 schedulers x 6 L1 sizes, each 18 lines of the frame rate
# against cores (a line per scheduler, the L1 sizes as further lines), where the first 10 of 18
# were drawn before.
python3 - <<'PY'
import json
with open("many.jsonl", "w") as f:
    for cores in (1, 2):
        for index, scheduler in enumerate(("cfa", "fa", "rr")):
            for size in (1, 2, 4, 8, 16, 32):
                config = {"cores": cores, "scheduler": scheduler, "memory.l1.size": "%dKiB" % size,
                          "width": 64, "height": 36, "scene": "menger"}
                stats = {"fps": 100.0 * cores + index + size / 100, "total_cycles": 1000}
                f.write(json.dumps({"status": "ok", "config": config, "statistics": stats}) + "\n")
PY
python3 "$script" plot --out-dir many many.jsonl >/dev/null || fail "plot of 36 rows"
[[ $(grep -c '<g id="series ' many/fps_vs_cores.svg) == 18 ]] \
  || fail "fps against cores: $(grep -c '<g id="series ' many/fps_vs_cores.svg) lines, not 18"
[[ $(grep -c '<g id="series ' many/fps_vs_scheduler.svg) == 12 ]] || fail "fps against scheduler: not 12 lines"

# The best configuration per scene, worked out by hand: menger's base (the first row: cfa,
# 4 KiB) 100 fps, its best fa 4 KiB 110 fps: +10.00 %; terrain's base 200 fps, its best rr
# 16 KiB 250 fps: +25.00 %. With the L1 size as a second objective, menger's Pareto front is
# fa 4 KiB (110 fps) and cfa 2 KiB (95 fps, smaller), not rr 16 KiB (105 fps, larger).
python3 - <<'PY'
import json
fps = {("menger", "cfa", 4): 100.0, ("menger", "fa", 4): 110.0, ("menger", "rr", 16): 105.0,
       ("menger", "cfa", 2): 95.0,
       ("terrain", "cfa", 4): 200.0, ("terrain", "fa", 4): 190.0, ("terrain", "rr", 16): 250.0,
       ("terrain", "cfa", 2): 180.0}
with open("best.jsonl", "w") as f:
    for (scene, scheduler, size), value in fps.items():
        config = {"scene": scene, "scheduler": scheduler, "memory.l1.size": "%dKiB" % size}
        f.write(json.dumps({"status": "ok", "preset": "cached", "config": config,
                            "statistics": {"fps": value, "memory": {"l1": {"hit_rate": 0.5}}}}) + "\n")
PY
python3 "$script" best best.jsonl >best.txt || fail "best"
grep -q "base: scheduler cfa, L1 size 4 KiB" best.txt || fail "best: base $(cat best.txt)"
grep -q "scene menger: best #2 scheduler fa, L1 size 4 KiB: fps 110; base #1 100: gain +10.00 %" best.txt \
  || fail "best for menger: $(cat best.txt)"
grep -q "scene terrain: best #7 scheduler rr, L1 size 16 KiB: fps 250; base #5 200: gain +25.00 %" best.txt \
  || fail "best for terrain: $(cat best.txt)"
python3 "$script" best --objective fps --objective min:memory.l1.size best.jsonl >pareto.txt \
  || fail "best with two objectives"
sed -n '/scene menger/,/scene terrain/p' pareto.txt | grep '^    #' | cut -d: -f1 >front.txt
[[ $(cat front.txt) == $'    #2 scheduler fa, L1 size 4 KiB\n    #4 scheduler cfa, L1 size 2 KiB' ]] \
  || fail "menger's Pareto front: $(cat pareto.txt)"
# `cores` as an objective is the setting, not the per-core statistics of the same name: 1 core at
# 100.01 fps and 2 at 200.01 are both on the front of the most fps for the fewest cores.
python3 "$script" best --objective fps --objective min:cores --where scheduler=cfa \
  --where memory.l1.size=1KiB many.jsonl >cores.txt || fail "best --objective min:cores"
grep -q "Pareto front of fps (higher is better) and cores (lower is better) (2 of 2 rows)" cores.txt \
  || fail "best with min:cores: $(cat cores.txt)"
# The base named: rr 16 KiB; frame time as the objective gives the same gain as the rate.
python3 "$script" best --base scheduler=rr --base memory.l1.size=16KiB best.jsonl >based.txt
grep -q "scene terrain: best #7 .*base #7 250: gain +0.00 %" based.txt || fail "--base: $(cat based.txt)"
expect_error "say max:total_bits or min:total_bits" python3 "$script" best --objective total_bits best.jsonl

# The report: the best configuration, a sortable table with the best rows marked, hit rates
# and the preset per row.
python3 "$script" report --out best.html best.jsonl >/dev/null || fail "report of best.jsonl"
grep -q '<table id="rows" class="sortable">' best.html || fail "report: no sortable table"
grep -q '<table id="best">' best.html || fail "report: no best configuration"
[[ $(grep -c '<tr class="best"><td class="num" data-sort="[27]">' best.html) == 2 ]] \
  || fail "report: rows 2 and 7 not marked best"
grep -q "<th>L1 hit rate</th>" best.html || fail "report: no hit rates"
grep -q "<td>cached</td>" best.html || fail "report: no preset per row"

# Sorting in a browser (when chromium is installed): two clicks on the fps heading order the rows
# by fps, highest first. Two inputs, so that the comparison's sortable table comes before.
if command -v chromium >/dev/null; then
  cp best.jsonl again.jsonl
  python3 "$script" report --out two.html best.jsonl again.jsonl >/dev/null || fail "report of two inputs"
  sed 's|</body>|<script>var h = Array.from(document.querySelectorAll("#rows th")).find(function (t) { return t.textContent == "fps"; }); h.click(); h.click();</script></body>|' \
    two.html >clicked.html
  timeout 60 chromium --headless --no-sandbox --disable-gpu --dump-dom clicked.html 2>/dev/null >dom.html
  python3 - <<'PY' || fail "report: the rows table does not sort by fps"
import re
table = open("dom.html").read().split('<table id="rows"')[1].split("</table>")[0]
column = re.findall(r"<th[^>]*>(.*?)</th>", table).index("fps")
fps = [float(re.findall(r"<td[^>]*>(.*?)</td>", row)[column])
       for row in re.findall(r"<tr[^>]*>(.*?)</tr>", table)[1:]]
assert fps == [v for v in (250, 200, 190, 180, 110, 105, 100, 95) for _ in (0, 1)], fps
PY
else
  echo "no chromium: the sorting in a browser is not checked"
fi

# diff of two runs: the configuration difference first, then every statistic with B - A and B / A.
printf '{"preset":"","config":{"scheduler":"cfa","cores":4},"statistics":{"fps":100.0,"total_cycles":1000,"limit":"cores","memory":{"l1":{"hit_rate":0.5}}}}\n' >a.json
printf '{"preset":"","config":{"scheduler":"fa","cores":4},"statistics":{"fps":125.0,"total_cycles":800,"limit":"memory","memory":{"l1":{"hit_rate":0.5}}}}\n' >b.json
python3 "$script" diff a.json b.json >diff.txt || fail "diff"
[[ $(sed -n 3p diff.txt | tr -s ' ') == " scheduler cfa fa" ]] || fail "diff: the configuration first: $(cat diff.txt)"
grep -q "^  fps  *100  *125  *25.0  *1.2500$" diff.txt || fail "diff: fps $(cat diff.txt)"
grep -q "^  total_cycles  *1000  *800  *-200  *0.8000$" diff.txt || fail "diff: total_cycles $(cat diff.txt)"
grep -q "^  limit  *cores  *memory  *differs" diff.txt || fail "diff: limit $(cat diff.txt)"
# diff and best draw nothing: they run where matplotlib cannot be imported.
RTUSIM_PLOT_REEXEC=1 python3 -c 'import os, runpy, sys
sys.modules["matplotlib"] = None  # import matplotlib raises ImportError
sys.argv = sys.argv[1:]
sys.path.insert(0, os.path.dirname(sys.argv[0]))  # as running the script itself does
runpy.run_path(sys.argv[0], run_name="__main__")' "$script" diff a.json b.json >nompl.txt \
  || fail "diff needs matplotlib"
cmp -s diff.txt nompl.txt || fail "diff without matplotlib differs"
python3 "$script" diff --changed a.json b.json >changed.txt
! grep -q hit_rate changed.txt || fail "diff --changed shows an equal statistic"

# --pareto: frame rate against a resource of the rows' estimate (issue 30 §2). Four architectures
# at two sizes, by hand: (block RAMs, fps) svo (2, 10) (8, 30), bvh (4, 8) (16, 50),
# bih (3, 20) (12, 40), kd (6, 5) (24, 15). The front, by fewest RAMs at the highest fps:
# svo 2/10, bih 3/20, svo 8/30, bih 12/40, bvh 16/50; bvh 4/8, kd 6/5, kd 24/15 are beaten.
python3 - <<'EOF2'
import json
points = {"svo": [(2, 0, 10), (8, 0, 30)], "bvh": [(4, 24, 8), (16, 96, 50)],
          "bih": [(3, 48, 20), (12, 192, 40)], "kd": [(6, 40, 5), (24, 160, 15)]}
rows = []
for core, sizes in points.items():
    for cores, (rams, dsps, fps) in zip((4, 16), sizes):
        rows.append({"status": "ok", "error": "", "config": {"core": core, "cores": cores},
                     "statistics": {"fps": fps, "total_cycles": 1000},
                     "resources": {"bram18k": rams, "dsp48e": dsps, "memories": []}})
with open("resources.jsonl", "w") as f:
    f.write("\n".join(json.dumps(r) for r in rows) + "\n")
EOF2
python3 "$script" plot --pareto bram18k --out-dir pareto resources.jsonl >pareto.txt \
  || fail "plot --pareto exit status"
magic pareto/pareto_fps_vs_bram18k.png 89504e470d0a1a0a
grep -q 'id="pareto front"' pareto/pareto_fps_vs_bram18k.svg || fail "no Pareto front drawn"
[[ $(wc -l <pareto.txt) == 2 ]] || fail "plot --pareto wrote more than its plot"
PYTHONPATH=$(dirname "$script") python3 -c '
import sys
from rtusim_rows import load
from rtusim_objective import resource_front
front = [(r["config"]["core"], r["resources"]["bram18k"]) for r in resource_front(load(["resources.jsonl"]), "bram18k", "fps")]
expected = [("svo", 2), ("bih", 3), ("svo", 8), ("bih", 12), ("bvh", 16)]
sys.exit(0 if front == expected else "front %s, expected %s" % (front, expected))' \
  || fail "the Pareto front is not the hand-derived one"
expect_error "pareto luts: no ok row has both fps and luts" \
  python3 "$script" plot --pareto luts --out-dir bad resources.jsonl

head -2 fps.csv >one.csv
expect_error "no plot applies" python3 "$script" plot --out-dir bad one.csv
expect_error "usage" python3 "$script" plot sweep.jsonl
expect_error "by schedular: no row has the key schedular" \
  python3 "$script" plot --x cores --by schedular --out-dir bad sweep.jsonl
expect_error "y fsp: no ok row has a number" python3 "$script" plot --y fsp --out-dir bad sweep.jsonl
echo "plot script: all checks passed"
