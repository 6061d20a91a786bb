#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite through CTest.
set -euo pipefail
cd "$(dirname "$0")"
source scripts/setup.sh
ctest --test-dir build --output-on-failure -j "$(nproc)" "$@"
