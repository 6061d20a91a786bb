#!/usr/bin/env bash
# The CGAL meshes the triangle benchmarks measure (Debian's libcgal-demo: Stanford-derived scans),
# fetched without installing the package (it pulls the whole CGAL development stack): the .deb is
# downloaded and only its meshes unpacked into build/cgal-meshes/. Prints the paths of the meshes
# named on the command line (default: armadillo, bunny00, ChineseDragon-10kv, refined_elephant).
#   bench/cgal_meshes.sh [name ...]      e.g. build/bench/triangle_bench $(bench/cgal_meshes.sh)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir=$root/build/cgal-meshes
names=("$@")
((${#names[@]})) || names=(armadillo bunny00 ChineseDragon-10kv refined_elephant)
if [[ ! -d $dir/data/meshes ]]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  (cd "$work" && apt-get download libcgal-demo >/dev/null 2>&1) ||
    { echo "cgal_meshes.sh: cannot download libcgal-demo from the Debian archive" >&2; exit 1; }
  dpkg-deb -x "$work"/libcgal-demo_*.deb "$work/deb"
  mkdir -p "$dir"
  tar -xzf "$work/deb/usr/share/doc/libcgal-dev/data.tar.gz" -C "$dir" --wildcards 'data/meshes/*'
fi
for name in "${names[@]}"; do
  path=$dir/data/meshes/$name.off
  [[ -f $path ]] || { echo "cgal_meshes.sh: no mesh '$name' in libcgal-demo" >&2; exit 1; }
  echo "$path"
done
