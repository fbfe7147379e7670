#!/bin/sh
# docs/commands.md and the man page's OPTIONS section are what the help texts and the options table
# compiled into footsim say. Usage: cli_docs_commands.sh path/to/footsim
out=$(mktemp) || exit 1
man=$(mktemp) || exit 1
trap 'rm -f "$out" "$man"' EXIT
fail=0
if ! sh tools/gen-commands-doc.sh "$1" > "$out"; then
    echo "tools/gen-commands-doc.sh failed" >&2
    fail=1
elif ! cmp -s "$out" docs/commands.md; then
    diff -u docs/commands.md "$out" | head -40 >&2
    echo "docs/commands.md is stale: run 'sh tools/gen-commands-doc.sh build/footsim > docs/commands.md'" >&2
    fail=1
fi
if ! sh tools/gen-commands-doc.sh "$1" --man docs/footsim.1 > "$man"; then
    echo "tools/gen-commands-doc.sh --man failed" >&2
    fail=1
elif ! cmp -s "$man" docs/footsim.1; then
    diff -u docs/footsim.1 "$man" | head -40 >&2
    echo "docs/footsim.1's OPTIONS are stale: run 'sh tools/gen-commands-doc.sh build/footsim --man docs/footsim.1 > new && mv new docs/footsim.1'" >&2
    fail=1
fi
[ $fail -eq 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $fail
