#!/bin/sh
# Writes docs/commands.md from the help texts compiled into footsim:
#   sh tools/gen-commands-doc.sh build/footsim > docs/commands.md
# and, with --man, the man page with its OPTIONS section made of the same options table:
#   sh tools/gen-commands-doc.sh build/footsim --man docs/footsim.1 > docs/footsim.1.new && mv docs/footsim.1.new docs/footsim.1
# The commands are those 'footsim --help' lists; each section is 'footsim COMMAND --help' verbatim,
# except the installed data folder, which depends on the build's prefix and is written as
# PREFIX/share/footsim. The man page's OPTIONS section (from '.SH OPTIONS' to the next '.SH') is
# 'footsim --help's option list, each option a .TP entry; the rest of the page is kept as it is.
# tests/cli_docs_commands.sh (ctest docs_commands) checks both committed files.
set -eu
fs=${1:-build/footsim}
norm() { sed 's|installed data ([^)]*)|installed data (PREFIX/share/footsim)|'; }
if [ "${2:-}" = --man ]; then
    page=${3:?gen-commands-doc.sh: --man needs the man page to rewrite}
    "$fs" --help | norm | sed -n '/^options \[/,/^$/p' | sed '1d;/^$/d' >"${TMPDIR:-/tmp}/fs-options.$$"
    [ -s "${TMPDIR:-/tmp}/fs-options.$$" ] || { echo "gen-commands-doc.sh: '$fs --help' lists no options" >&2; exit 1; }
    awk -v opts="${TMPDIR:-/tmp}/fs-options.$$" '
        function esc(s) { gsub(/\\/, "\\\\e", s); gsub(/-/, "\\\\-", s); return s }
        function emit() {
            if (!have) return
            print ".TP"
            if (value != "") print ".BI " esc(name) " \" " esc(value) "\""
            else print ".B " esc(name)
            print esc(text)
            have = 0
        }
        function options_section(   line, n, head, sp) {
            while ((getline line < opts) > 0) {
                if (line ~ /^  -/) {
                    emit()
                    line = substr(line, 3)
                    n = match(line, /   */)
                    head = n ? substr(line, 1, n - 1) : line
                    text = n ? substr(line, n) : ""
                    sub(/^ +/, "", text)
                    sp = index(head, " ")
                    if (sp && substr(head, sp - 1, 1) != ",") { name = substr(head, 1, sp - 1); value = substr(head, sp + 1) }
                    else { name = head; value = "" }
                    have = 1
                } else {
                    sub(/^ +/, "", line)
                    text = text (text != "" ? " " : "") line
                }
            }
            emit()
        }
        /^\.SH / { if (skipping) skipping = 0 }
        skipping { next }
        /^\.SH OPTIONS$/ { print; options_section(); skipping = 1; next }
        { print }
    ' "$page"
    rm -f "${TMPDIR:-/tmp}/fs-options.$$"
    exit 0
fi
cmds=$("$fs" --help | sed -n '/^commands:/,/^$/p' | sed -n 's/^  \([a-z][a-z-]*\).*/\1/p')
[ -n "$cmds" ] || { echo "gen-commands-doc.sh: '$fs --help' lists no commands" >&2; exit 1; }
echo "# Every command and its options"
echo
echo "Generated from \`footsim --help\` and \`footsim COMMAND --help\` by"
echo "\`sh tools/gen-commands-doc.sh build/footsim > docs/commands.md\`; do not edit it by hand (the"
echo "ctest test \`docs_commands\` fails when it is stale). See also the man page"
echo "([footsim.1](footsim.1)), whose OPTIONS section is made of the same table. Exit statuses: the"
echo "README's table. Keys of every file: [keys.md](keys.md); the files themselves: [files.md](files.md)."
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
