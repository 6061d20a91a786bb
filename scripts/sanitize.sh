#!/usr/bin/env bash
# The test suite under AddressSanitizer and UndefinedBehaviorSanitizer (float-cast-overflow
# included), built at -O1 into its own directory, build-sanitize/. Any finding fails the run.
# Leak checking stays on; only SystemC's by-design kernel leak is suppressed
# (tests/sanitizers/lsan.supp). Usage: scripts/sanitize.sh [extra ctest arguments]
set -euo pipefail
cd "$(dirname "$0")/.."
# The packages are those of scripts/setup.sh; .ci/run runs test.sh, which installs them, first.

# Build type "Sanitize" carries these flags alone: an empty build type fell back to the
# project's Release default, which appended -O3 -DNDEBUG (91 s instead of 36 s for one command
# file). -g1 (line tables) is enough for the sanitizers' stack traces and compiles faster than -g.
# The only C code is Verilator's FST writer, whose misaligned stores are by design (UBSan reports
# them): not ours to instrument.
flags="-O1 -g1 -fno-omit-frame-pointer -fsanitize=address,undefined,float-cast-overflow"
flags+=" -fno-sanitize-recover=all"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Sanitize -DCMAKE_CXX_FLAGS_SANITIZE="$flags" \
  -DCMAKE_C_FLAGS_SANITIZE="-O2 -g1" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_MODULE_LINKER_FLAGS="-fsanitize=address,undefined" -DRTUSIM_BENCH=OFF \
  -DRTUSIM_UNITY_BUILD=ON \
  "${launcher[@]}" >/dev/null
cmake --build build-sanitize -j "$(nproc)"

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:halt_on_error=1:strict_string_checks=1"
# use_tls=0: GCC 12's LeakSanitizer faults ("Tracer caught signal 11") scanning a bogus dynamic
# TLS range ("DTLS 8 at 0x4289-0x2c0000538b") after the OpenImageIO plug-in's threads ran (a
# cycle-accurate render writing four outputs); the library allocations then reachable only
# through TLS are suppressed by name (tests/sanitizers/lsan.supp).
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0:use_tls=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The Slurm test brings up daemons that are not ours to instrument; the plot tests are Python
# (plot_sweep's sweeps run in other tests);
# trace_memory asserts a resident-memory bound, which AddressSanitizer's shadow memory and
# quarantine inflate (about 490 MB for the 120 MB bound): it runs in the Release suite, as does
# out_of_memory, whose address-space limit AddressSanitizer cannot start under.
ctest --test-dir build-sanitize --output-on-failure -j "$(nproc)" \
  -E '^(slurm_sweep|plot_script|plot_sweep|trace_memory|out_of_memory)$' "$@"
