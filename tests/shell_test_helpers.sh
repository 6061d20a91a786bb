# Sourced by the shell tests: a scratch directory removed on exit, and the checks they share.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

fail() { echo "FAIL: $*" >&2; exit 1; }
expect_error() {  # expect_error "message part" command...
  local message=$1; shift
  if "$@" >out.txt 2>err.txt; then fail "'$*' succeeded"; fi
  grep -q -- "$message" err.txt || { cat err.txt >&2; fail "'$*' did not say '$message'"; }
}
