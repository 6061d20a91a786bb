#!/usr/bin/env bash
# The keys of the statistics JSON (render --stats with cached memory and a reorder buffer, and a
# sampled sweep row) are those recorded in tests/data/statistics_keys.txt, so that a renamed or
# lost key fails: scripts read them (issue 26); the ray pipe's (render --architecture raypipe
# --stats, and an fps row) those in tests/data/raypipe_statistics_keys.txt (issue 29).
# Usage: statistics_keys.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"

"$rtusim" render --scene menger --depth 5 --width 64 --height 36 --cores 4 --memory cached \
  --reorder 4 --stats cached.json >/dev/null
"$rtusim" sweep --preset cached --scene menger --depth 5 --width 320 --height 180 --grid cores=4 \
  --sample 0.3 --out sampled.csv -j 1 >/dev/null 2>&1
python3 "$here/statistics_keys.py" cached.json sampled.jsonl >keys.txt
diff "$here/data/statistics_keys.txt" keys.txt >keys.diff \
  || { cat keys.diff >&2; fail "the statistics keys differ from tests/data/statistics_keys.txt"; }

# The set-associative caches' keys too (with the block RAMs the caches' list is empty).
pipe=(--preset trayracer --scene sphere --depth 3 --index wide --set raypipe.cache=set_associative)
"$rtusim" render "${pipe[@]}" --level 0 --stats pipe.json >/dev/null
"$rtusim" fps "${pipe[@]}" --resolutions 20x15 --csv pipe.csv -j 1 >/dev/null 2>&1
python3 "$here/statistics_keys.py" pipe.json pipe.jsonl >pipe_keys.txt
diff "$here/data/raypipe_statistics_keys.txt" pipe_keys.txt >pipe_keys.diff \
  || { cat pipe_keys.diff >&2; fail "the ray pipe's statistics keys differ from tests/data/raypipe_statistics_keys.txt"; }
echo "statistics keys: ok"
