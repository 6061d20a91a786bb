#!/bin/bash
# scripts/check_layers.py's rules on small made-up trees (the include_layers test runs it on the
# real one): a kind's plug-in folder (kinds/<kind>/<layer>) sits at its layer, may include that
# layer and its own kind, never another kind nor a layer above; a kind's own folder includes no
# layer above the kinds.
set -euo pipefail
check="$(cd "$(dirname "$0")/.." && pwd)/scripts/check_layers.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

tree() {  # a fresh tree: base, kinds/*, kinds, explore, app; kinds a and b with explore plug-ins
  rm -rf "$work/src" && mkdir -p "$work/src"/{base,kinds/a/explore,kinds/b,explore,app}
  printf 'base\nkinds/*\nkinds\nexplore\napp\n' >"$work/src/layers.txt"
  for f in base/u.h kinds/a/a.h kinds/a/explore/plug.h kinds/b/b.h kinds/registry.h explore/scene.h \
    app/main.h; do
    : >"$work/src/$f"
  done
}
expect() {  # expect ok|fail FILE INCLUDE
  tree
  printf '#include "%s"\n' "$3" >"$work/src/$2"
  local status=0
  python3 "$check" "$work" >"$work/out.txt" || status=$?
  if [[ $1 == ok && $status -ne 0 ]] || [[ $1 == fail && $status -eq 0 ]]; then
    echo "FAIL: $2 including $3 should be $1:"; cat "$work/out.txt"; exit 1
  fi
}
expect ok kinds/a/explore/plug.h explore/scene.h     # its layer
expect ok kinds/a/explore/plug.h kinds/a/a.h         # its own kind
expect ok kinds/a/explore/plug.h kinds/registry.h    # below it
expect ok explore/scene.h kinds/a/explore/plug.h     # the layer sees its kinds' plug-ins
expect fail kinds/a/explore/plug.h kinds/b/b.h       # another kind
expect fail kinds/a/explore/plug.h app/main.h        # a layer above
expect fail kinds/a/a.h explore/scene.h              # the kind's own folder: below explore
expect fail kinds/a/a.h kinds/b/b.h                  # kinds never include each other
expect fail base/u.h kinds/a/explore/plug.h          # base is below every layer
echo "layer rules: ok"
