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
head -2 fps.csv >one.csv
expect_error "no plot applies" python3 "$script" plot --out-dir bad one.csv
expect_error "usage" python3 "$script" plot sweep.jsonl
echo "plot script: all checks passed"
