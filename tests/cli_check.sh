# Sourced by the cli_*.sh tests: $fs the footsim command (the test's first argument), $tmp a folder
# removed at exit, check 'CONDITION' (or check_that DESCRIPTION COMMAND...) to count a check, expect STATUS PATTERN -- ARGS to run footsim
# and check its exit status and stderr, long_dir LEN LETTER a long path, and finish to report "N passed, N failed" and
# set the exit status.
fs=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0 failed=0
check() { if eval "$1"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $1" >&2; fi; }
# check_that DESCRIPTION COMMAND...: COMMAND (run as given, not evaluated) must succeed
check_that() {
    what=$1
    shift
    if "$@"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $what" >&2; fi
}
# expect STATUS PATTERN -- ARGS...: footsim ARGS exits STATUS with PATTERN on stderr
expect() {
    want=$1 pattern=$2
    shift 3
    "$fs" "$@" >"$tmp/out" 2>"$tmp/err"
    got=$?
    if [ "$got" -eq "$want" ] && grep -q -- "$pattern" "$tmp/err"; then
        passed=$((passed + 1))
    else
        failed=$((failed + 1))
        echo "FAIL: footsim $* gave status $got (wanted $want); stderr:" >&2
        cat "$tmp/err" >&2
        echo "  (wanted it to contain: $pattern)" >&2
    fi
}
# long_dir LEN LETTER: a folder path under $tmp of LEN characters (components of 200 LETTERs, then
# one shorter), for the tests of paths never cut short
long_dir() {
    p=$tmp
    while [ $(($1 - ${#p})) -gt 201 ]; do p=$p/$(printf "%0200d" 0 | tr 0 "$2"); done
    echo "$p/$(printf "%0$(($1 - ${#p} - 1))d" 0 | tr 0 "$2")"
}
finish() {
  echo "${1:+$1: }$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}
