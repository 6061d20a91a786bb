#!/usr/bin/env bash
# Checks that every tracked C/C++ source follows .clang-format (CTest's format_check). Exits 0 when all do, 1 naming the files that
# differ, 2 when clang-format itself fails (e.g. a broken .clang-format), and 77 (CTest's
# SKIP_RETURN_CODE) without clang-format or outside a git checkout. CLANG_FORMAT picks the binary
# (default: clang-format). .clang-format was written for clang-format 14 (Debian 12); other
# versions may format a few constructs differently.
# To fix the files it names: clang-format -i FILE...
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

clang_format=${CLANG_FORMAT:-clang-format}
if ! command -v "$clang_format" >/dev/null 2>&1; then
  echo "check_format: $clang_format not found, skipped (apt-get install clang-format)" >&2
  exit 77
fi
if ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  echo "check_format: not a git checkout, no list of tracked files, skipped" >&2
  exit 77
fi
if [[ ! -f .clang-format ]]; then
  echo "check_format: .clang-format missing" >&2
  exit 2
fi

# Sources not ours to format, as git pathspecs, each with its reason. None today: the only
# third-party C code, GTKWave's fstapi.c and its compressors, is compiled from Debian's verilator
# package (src/trace/CMakeLists.txt) and is not in the tree; src/trace/fst_writer.cpp is our
# own code calling it.
exclusions=(
)

pathspecs=('*.h' '*.hpp' '*.c' '*.cc' '*.cpp')
for excluded in "${exclusions[@]}"; do pathspecs+=(":(exclude)$excluded"); done
mapfile -t files < <(git ls-files -- "${pathspecs[@]}")
if ((${#files[@]} == 0)); then
  echo "check_format: no C/C++ sources found" >&2
  exit 2
fi

version=$("$clang_format" --version)
status=0
output=$(printf '%s\0' "${files[@]}" |
  xargs -0 "$clang_format" --dry-run --Werror --style=file 2>&1) || status=$?
if ((status == 0)); then
  echo "check_format: ${#files[@]} files follow .clang-format ($version)"
  exit 0
fi

# One "FILE:LINE:COLUMN: error: code should be clang-formatted" line per difference.
mapfile -t differing < <(sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' \
  <<<"$output" | uniq -c | awk '{print $2 " (" $1 ($1 == 1 ? " place" : " places") ")"}')
if ((${#differing[@]} == 0)); then
  echo "check_format: $clang_format failed ($version):" >&2
  echo "$output" >&2
  exit 2
fi
echo "check_format: ${#differing[@]} of ${#files[@]} files differ from .clang-format ($version):" >&2
printf '  %s\n' "${differing[@]}" >&2
echo "Fix them with: clang-format -i FILE... (the first differences follow)" >&2
head -n 40 <<<"$output" >&2
exit 1
