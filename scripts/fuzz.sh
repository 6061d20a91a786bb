#!/usr/bin/env bash
# Mutation fuzzing of every input format rtusim reads (tests/fuzz/fuzz_inputs.py), on the
# Release build in build/. Failing mutants (crash, hang, error not naming the file) are kept in
# tests/fuzz/corpus/<format>/, which the malformed_files test replays.
#   scripts/fuzz.sh                          100 mutants per format, seed from the clock
#   scripts/fuzz.sh --mutants 500 --formats ply,obj --seed 7
set -euo pipefail
root_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
[[ -x "$root_dir/build/rtusim" ]] || { echo "fuzz.sh: build rtusim first (./run.sh or cmake)" >&2; exit 1; }
exec python3 "$root_dir/tests/fuzz/fuzz_inputs.py" "$root_dir/build/rtusim" --mutants 100 \
  --seed "$(date +%s)" --save "$root_dir/tests/fuzz/corpus" "$@"
