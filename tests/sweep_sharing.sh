#!/usr/bin/env bash
# Issue 33, section 2: sweeps share their results safely. A second sweep into the same --out with
# another grid keeps the earlier rows; two sweeps at once on one --out: the second is refused,
# naming the first's pid and host; the workers of a killed sweep die with it; a Slurm sweep
# clears only a plan directory it made.
# Usage: sweep_sharing.sh path/to/rtusim
set -euo pipefail
rtusim=$1
source "$(dirname "${BASH_SOURCE[0]}")/shell_test_helpers.sh"
small=(--scene sphere --depth 4 --width 8 --height 8 -j 1)

# Another grid into the same files: the earlier rows stay, each configuration once.
"$rtusim" sweep "${small[@]}" --grid cores=1,2 --out rows.csv >/dev/null
"$rtusim" sweep "${small[@]}" --grid cores=3 --out rows.csv >second.txt
grep -q "0 already done, 1 to run with 1 workers; 2 rows of other configurations kept" second.txt ||
  fail "summary of the second sweep: $(cat second.txt)"
[[ $(wc -l <rows.jsonl) -eq 3 && $(wc -l <rows.csv) -eq 4 ]] || fail "earlier rows deleted"
"$rtusim" sweep "${small[@]}" --grid cores=1,2,3 --out rows.csv >third.txt
grep -q "3 already done, 0 to run" third.txt || fail "kept rows not taken as done"
[[ $(wc -l <rows.jsonl) -eq 3 ]] || fail "a kept row was written twice"

# A Slurm plan's directory is cleared only when a sweep made it.
mkdir mine && echo keep >mine/notes.txt
expect_error "sweep directory '$PWD/mine' exists and is not one a sweep made" \
  "$rtusim" sweep "${small[@]}" --grid cores=1 --out plan.csv --slurm --dry-run --sweep-dir mine
[[ -f mine/notes.txt ]] || fail "the sweep deleted a directory it did not make"
"$rtusim" sweep "${small[@]}" --grid cores=1 --out plan.csv --slurm --dry-run >/dev/null
"$rtusim" sweep "${small[@]}" --grid cores=1,2 --out plan.csv --slurm --dry-run >/dev/null
grep -q '"rows":"0-1"' plan.slurm/plan.json || fail "a sweep's own plan was not replaced"
# A plan holds the rows not done as index ranges: rows.csv has cores 1, 2 and 3 done.
"$rtusim" sweep "${small[@]}" --grid cores=1,2,3,4 --grid scheduler=cfa,rr --out rows.csv \
  --slurm --dry-run --sweep-dir resumed >resumed.txt
grep -q "3 already done, 5 to run" resumed.txt || fail "resumed plan: $(cat resumed.txt)"
grep -q '"rows":"1-1,3-3,5-7"' resumed/plan.json || fail "resumed plan's rows"

# A slow sweep (rows of a few seconds each) in the background, its own process group.
slow=(--scene menger --depth 7 --width 1920 --height 1080 --memory cached --grid cores=1,2,3,4 -j 2)
setsid "$rtusim" sweep "${slow[@]}" --out slow.csv >slow.txt 2>&1 &
leader=$!
for _ in $(seq 1 200); do
  [[ -s slow.csv.lock ]] && break
  sleep 0.05
done
[[ -s slow.csv.lock ]] || fail "no lock file"
expect_error "sweep output 'slow.csv' is in use by process $leader on host $(hostname)" \
  "$rtusim" sweep "${slow[@]}" --out slow.csv
# Its workers die with it: kill the sweep alone (not its group).
for _ in $(seq 1 200); do
  workers=$(pgrep -P "$leader" || true)
  [[ -n $workers ]] && break
  sleep 0.05
done
[[ -n $workers ]] || fail "no workers running"
kill -KILL "$leader"
wait "$leader" 2>/dev/null || true
for _ in $(seq 1 100); do
  alive=$(for pid in $workers; do kill -0 "$pid" 2>/dev/null && echo "$pid"; done || true)
  [[ -z $alive ]] && break
  sleep 0.05
done
if [[ -n $alive ]]; then
  kill -KILL $alive 2>/dev/null || true
  fail "workers $alive outlived the killed sweep"
fi
# The lock went with the sweep: the next one resumes.
"$rtusim" sweep "${small[@]}" --grid cores=1 --out slow.csv >/dev/null
echo "sweep sharing: all checks passed"
