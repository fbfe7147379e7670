#!/bin/sh
# Writes docs/commands.md from the help texts compiled into footsim:
#   sh tools/gen-commands-doc.sh build/footsim > docs/commands.md
# The commands are those 'footsim --help' lists; each section is 'footsim COMMAND --help' verbatim,
# except the installed data folder, which depends on the build's prefix and is written as
# PREFIX/share/footsim. tests/cli_docs_commands.sh (ctest docs_commands) checks the committed file.
set -eu
fs=${1:-build/footsim}
norm() { sed 's|installed data ([^)]*)|installed data (PREFIX/share/footsim)|'; }
cmds=$("$fs" --help | sed -n '/^commands:/,/^$/p' | sed -n 's/^  \([a-z][a-z-]*\).*/\1/p')
[ -n "$cmds" ] || { echo "gen-commands-doc.sh: '$fs --help' lists no commands" >&2; exit 1; }
echo "# Every command and its options"
echo
echo "Generated from \`footsim --help\` and \`footsim COMMAND --help\` by"
echo "\`sh tools/gen-commands-doc.sh build/footsim > docs/commands.md\`; do not edit it by hand (the"
echo "ctest test \`docs_commands\` fails when it is stale). See also the man page"
echo "([footsim.1](footsim.1)). Exit statuses: the README's table. Keys of every file: [keys.md](keys.md);"
echo "the files themselves: [files.md](files.md)."
echo
echo "## Overview"
echo
echo '```text'
"$fs" --help | norm
echo '```'
for c in $cmds; do
    echo
    echo "## $c"
    echo
    echo '```text'
    "$fs" "$c" --help | norm
    echo '```'
done
