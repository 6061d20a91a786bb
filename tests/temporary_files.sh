#!/usr/bin/env bash
# Issue 33: an output's temporary file (".NAME.part-HOST-PID-XXXXXX.EXT" beside it) does not
# outlive its process. SIGTERM and SIGINT remove it before the process ends by the signal; after
# SIGKILL, which cannot be caught, the next output to the same path removes it. `render --image`
# writes its PNG file row by row as the frame runs, so its temporary file exists during the run.
# Usage: temporary_files.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"

set -m  # background jobs keep SIGINT (without job control bash ignores it in them)

parts() { compgen -G '.frame.part-*.png' || true; }

# Starts a long render into frame.png in the background and waits until its temporary file
# exists; the render's pid in $render.
start_render() {
  "$rtusim" render --model ca --width 1920 --height 1080 --image frame.png >/dev/null 2>&1 &
  render=$!
  for _ in $(seq 600); do
    [[ -n $(parts) ]] && return
    kill -0 "$render" 2>/dev/null || fail "the render ended before its temporary file was seen"
    sleep 0.05
  done
  fail "no temporary file of the render appeared"
}

for signal in TERM INT; do
  start_render
  [[ $(parts) == .frame.part-*-"$render"-*.png ]] || fail "temporary file not named by pid: $(parts)"
  kill -s "$signal" "$render"
  status=0
  wait "$render" || status=$?
  ((status > 128)) || fail "SIG$signal: the render exited with $status, not by the signal"
  [[ -z $(parts) ]] || fail "SIG$signal left $(parts)"
  [[ ! -e frame.png ]] || fail "SIG$signal left a frame.png"
done

start_render
kill -s KILL "$render"
wait "$render" || true
left=$(parts)
[[ -n $left ]] || fail "SIGKILL left no temporary file (the test needs one)"
"$rtusim" render --model golden --width 32 --height 24 --image frame.png >/dev/null
[[ -z $(parts) ]] || fail "the next render to frame.png left $(parts)"
[[ -s frame.png ]] || fail "the next render wrote no frame.png"
echo "temporary files: removed on SIGTERM and SIGINT, and after SIGKILL by the next run"
