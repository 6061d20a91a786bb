#!/usr/bin/env bash
# A full trace streams to its file with bounded memory (src/trace/cycle_trace.h): a 320x180 frame
# at 16 cores with cached memory, every signal traced (a 38 MB VCD), peaks under 120 MB resident
# (measured: 31 MB; untraced: 27 MB). Holding every record until the end, as rtusim did before,
# took 314 MB for this frame, so the bound fails if the trace is no longer streamed.
# Usage: trace_memory.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"

# The trace goes through a pipe to a byte count, not to the disk.
mkfifo trace.vcd
wc -c <trace.vcd >trace_bytes.txt &
"$rtusim" build --scene sphere --depth 8 --out sphere.svo >/dev/null
"$rtusim" jobs --width 320 --height 180 --out jobs.bin >/dev/null
peak_kb=$(python3 - "$rtusim" <<'PY'
import resource, subprocess, sys
subprocess.run([sys.argv[1], "replay", "--svo", "sphere.svo", "--jobs", "jobs.bin", "--out",
                "results.bin", "--cores", "16", "--memory", "cached", "--vcd", "trace.vcd"],
               check=True, stdout=subprocess.DEVNULL)
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
PY
)
wait
trace_mb=$(( $(<trace_bytes.txt) / 1000000 ))
echo "peak resident ${peak_kb} KB while writing a ${trace_mb} MB trace"
(( trace_mb > 30 )) || fail "the trace is only ${trace_mb} MB: the frame no longer tests the bound"
(( peak_kb < 120000 )) || fail "peak resident ${peak_kb} KB, not under 120 MB"
