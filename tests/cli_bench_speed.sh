#!/bin/sh
# footsim bench speed --quick writes its files, whole, with a row per scene and per skip; a folder
# it cannot make is refused (exit 2) before anything is measured. No timing is checked.
# Usage: cli_bench_speed.sh path/to/footsim (run from the source folder).
. "$(dirname "$0")/cli_check.sh"
"$fs" bench speed --quick --out "$tmp/bench" >/dev/null 2>"$tmp/err"
status=$?
check '[ "$status" -eq 0 ]'
for f in speed.csv skips.csv speed.md speed.gp; do
    check '[ -s "$tmp/bench/$f" ]'
done
if command -v gnuplot >/dev/null; then check '[ -s "$tmp/bench/speed.png" ]'; fi
check '[ -z "$(ls "$tmp/bench" | grep tmp)" ]'
check 'grep -q "^scene,runner,runs,steps,sim_s,step_s,wall_s,steps_per_s,rtf" "$tmp/bench/speed.csv"'
check '[ "$(grep -c "^static_load," "$tmp/bench/speed.csv")" -eq 1 ]'
check '[ "$(grep -vc "^#" "$tmp/bench/skips.csv")" -ge 6 ]'
check 'grep -q "^# machine: " "$tmp/bench/speed.csv"'
check 'grep -q "own code takes at most" "$tmp/bench/speed.md"'
# every skip row's saving is a number, and the stage shares of every scene add up to 100 %
check 'awk -F, "!/^#/ && NR > 3 { s = \$12 + \$13 + \$14; if (s < 99.8 || s > 100.2) bad = 1 } END { exit bad }" "$tmp/bench/speed.csv"'
# a folder it cannot write: refused at once
touch "$tmp/file"
"$fs" bench speed --quick --out "$tmp/file/bench" >/dev/null 2>&1
status=$?
check '[ "$status" -eq 2 ]'
finish
