#!/usr/bin/env bash
# Screenshots of GTKWave showing rtusim traces, for docs/waveforms.md: runs GTKWave under Xvfb
# on a small FST with the save file rtusim writes next to it, and grabs the screen with
# ImageMagick's import. Packages: gtkwave, xvfb, imagemagick (scripts/setup.sh installs them).
# Usage: scripts/waveform_screenshots.sh [path/to/rtusim] [output directory, default docs/images]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rtusim=$(realpath "${1:-$here/../build/rtusim}")
out=$(realpath -m "${2:-$here/../docs/images}")
for tool in gtkwave Xvfb import; do
  command -v $tool >/dev/null || { echo "$tool not found: run scripts/setup.sh" >&2; exit 1; }
done
mkdir -p "$out"
work=$(mktemp -d)
display=:$((90 + RANDOM % 100))
cleanup() { [[ -n ${xvfb:-} ]] && kill "$xvfb" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
cd "$work"

"$rtusim" build --scene sphere --depth 5 --out sphere.svo >/dev/null
"$rtusim" jobs --width 16 --height 12 --out jobs.bin >/dev/null
Xvfb "$display" -screen 0 1600x900x24 -nolisten tcp &
xvfb=$!
sleep 1

# shot NAME REPLAY-OPTIONS...: a trace of the first cycles, opened with its save file as rtusim
# writes it (its window size, view and zoom), grabbed once GTKWave has drawn it.
shot() {
  local name=$1; shift
  "$rtusim" replay --svo sphere.svo --jobs jobs.bin --out out.bin "$@" --trace "$name.fst" >/dev/null
  DISPLAY=$display gtkwave "$name.fst" "$name.fst.gtkw" >/dev/null 2>&1 &
  local viewer=$!
  sleep 4
  DISPLAY=$display import -window root "$out/$name.png"
  kill "$viewer"
  wait "$viewer" 2>/dev/null || true
  echo "wrote $out/$name.png"
}

# The pipeline at the start of a frame: host in, scheduler, two of four cores, result manager.
shot waveform_pipeline --cores 4 --trace-to 200 --trace-clock \
  --trace-scope rtu.job_manager rtu.scheduler rtu.core_0 rtu.core_1 rtu.result_manager
# Cached memory: cores BLOCKED on their reads, the L1 counters.
shot waveform_cached --cores 2 --memory cached --trace-to 400 \
  --trace-scope rtu.core_0 rtu.core_1 rtu.memory

# Seed 001's ray pipe (docs/raypipe.md, "Traces and timeline"): one hitting ray's window on a voxel
# sphere's faces at 20x15, its units and three FIFOs.
"$rtusim" render --preset trayracer --scene sphere --depth 3 --index wide --level 0 \
  --trace-ray 181 --trace waveform_raypipe.fst --trace-scope raypipe.sint raypipe.tarb \
  raypipe.trav raypipe.larb raypipe.int raypipe.list raypipe.shader_return raypipe.fifos.tarb \
  raypipe.fifos.pixel_buffer raypipe.fifos.shader_ray_ids >/dev/null
DISPLAY=$display gtkwave waveform_raypipe.fst waveform_raypipe.fst.gtkw >/dev/null 2>&1 &
viewer=$!
sleep 4
DISPLAY=$display import -window root "$out/waveform_raypipe.png"
kill "$viewer"
wait "$viewer" 2>/dev/null || true
echo "wrote $out/waveform_raypipe.png"
