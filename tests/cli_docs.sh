#!/bin/sh
# docs/keys.md is what the schemas compiled into footsim say. Usage: cli_docs.sh path/to/footsim
if sh tools/gen-keys-doc.sh "$1" | cmp -s - docs/keys.md; then
    echo "1 passed, 0 failed"
else
    echo "docs/keys.md is stale: run 'sh tools/gen-keys-doc.sh build/footsim > docs/keys.md'" >&2
    echo "0 passed, 1 failed"
    exit 1
fi
