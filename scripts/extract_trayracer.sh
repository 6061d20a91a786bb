#!/bin/sh
# Extracts the Tray Racer team's scene files, models and scene descriptions (seed 001's public
# repository, github.com/ryanmacdonald/18-545 at 81a34cd) from a mirror into build/trayracer/, for
# the byte-for-byte tests of tests/test_kd_trayracer_files.cpp. The repository has no licence:
# rtusim never commits its files, the tests read them at run time:
#   scripts/extract_trayracer.sh [GIT_DIR] [OUT_DIR]
#   RTUSIM_TRAYRACER_DIR=build/trayracer ./build/tests/rtusim_tests "[kd_r1]"
# GIT_DIR defaults to the mirror /work/.mirror/ryanmacdonald+18-545/repo (a bare clone works too).
set -eu
git_dir=${1:-/work/.mirror/ryanmacdonald+18-545/repo}
out=${2:-build/trayracer}
# File by file: a mirror may lack some large blobs (a model the tests do not read).
git --git-dir="$git_dir" ls-tree -r --name-only HEAD SCENES SOFTWARE/models SOFTWARE/scenes |
  while read -r path; do
    mkdir -p "$out/$(dirname "$path")"
    git --git-dir="$git_dir" show "HEAD:$path" >"$out/$path" 2>/dev/null || {
      rm -f "$out/$path"
      echo "skipped $path (not in the mirror)"
    }
  done
echo "extracted into $out; run the tests with RTUSIM_TRAYRACER_DIR=$out"
