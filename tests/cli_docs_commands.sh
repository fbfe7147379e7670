#!/bin/sh
# docs/commands.md is what the help texts compiled into footsim say. Usage: cli_docs_commands.sh path/to/footsim
out=$(mktemp) || exit 1
trap 'rm -f "$out"' EXIT
if ! sh tools/gen-commands-doc.sh "$1" > "$out"; then
    echo "tools/gen-commands-doc.sh failed" >&2
    echo "0 passed, 1 failed"
    exit 1
fi
if cmp -s "$out" docs/commands.md; then
    echo "1 passed, 0 failed"
else
    diff -u docs/commands.md "$out" | head -40 >&2
    echo "docs/commands.md is stale: run 'sh tools/gen-commands-doc.sh build/footsim > docs/commands.md'" >&2
    echo "0 passed, 1 failed"
    exit 1
fi
