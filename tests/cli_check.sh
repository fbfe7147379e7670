# Sourced by the cli_*.sh tests: $fs the footsim command (the test's first argument), $tmp a folder
# removed at exit, check 'CONDITION' to count a check, and finish to report "N passed, N failed" and
# set the exit status.
fs=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0 failed=0
check() { if eval "$1"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $1" >&2; fi; }
finish() {
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}
