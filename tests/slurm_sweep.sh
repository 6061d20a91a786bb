#!/usr/bin/env bash
# rtusim sweep --slurm on a real single-node Slurm cluster started for the test: its rows equal
# the local sweep's; resume and the dry run's batch script. Exit 77 (skipped) without root or
# without the Slurm and munge programs. Usage: slurm_sweep.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "$0")" && pwd)
cluster=$here/slurm_local_cluster.sh
if [[ $(id -u) -ne 0 ]] || ! "$cluster" available; then
  echo "slurm sweep: skipped (needs root and slurm-wlm + munge)"
  exit 77
fi
work=$(mktemp -d)
trap '"$cluster" stop "$work/cluster" >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
cd "$work"
python=/usr/bin/python3
[[ -x $python ]] || python=python3
fail() { echo "FAIL: $*" >&2; exit 1; }

sweep=(--scene sphere --depth 5 --width 24 --height 16 --grid cores=1,4 --grid scheduler=cfa,rr)
"$rtusim" sweep "${sweep[@]}" -j 2 --out local.csv >/dev/null

# The dry run writes the batch script without submitting anything.
"$rtusim" sweep "${sweep[@]}" --slurm --dry-run --slurm-partition debug --slurm-tasks 3 \
  --out dry.csv >dry.txt
grep -q '^#SBATCH --array=0-2$' dry.slurm/sweep.sbatch || fail "dry run: array"
grep -q '^#SBATCH --partition=debug$' dry.slurm/sweep.sbatch || fail "dry run: partition"
[[ -s dry.slurm/scenes.json ]] && grep -q '"rows":"0-3"' dry.slurm/plan.json || fail "dry run: plan"
[[ ! -s dry.jsonl ]] || fail "dry run ran rows"

mkdir cluster
eval "$("$cluster" start "$work/cluster")"
# Three of the four rows through two array elements, then the fourth on a resumed run.
"$rtusim" sweep --scene sphere --depth 5 --width 24 --height 16 --grid cores=1,4 \
  --grid scheduler=cfa --slurm --slurm-tasks 2 --out slurm.csv >first.txt
[[ $(wc -l <slurm.jsonl) -eq 2 ]] || { cat first.txt; fail "slurm sweep rows"; }
"$rtusim" sweep "${sweep[@]}" --slurm --out slurm.csv >second.txt
grep -q "2 already done" second.txt || fail "slurm resume"
[[ $(wc -l <slurm.jsonl) -eq 4 ]] || fail "slurm rows after resume"

# Same rows as the local sweep (but for host times), whatever their order.
"$python" - local.jsonl slurm.jsonl <<'PY' || fail "slurm rows differ from local rows"
import json, sys
def rows(path):
    out = {}
    for line in open(path):
        row = json.loads(line)
        row["statistics"].pop("simulation")
        out[json.dumps(row["config"], sort_keys=True)] = row
    return out
a, b = rows(sys.argv[1]), rows(sys.argv[2])
sys.exit(0 if a == b and len(a) == 4 else 1)
PY
echo "slurm sweep: ok"
