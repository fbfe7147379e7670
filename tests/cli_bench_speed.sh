#!/bin/sh
# footsim bench speed --quick writes its files, whole, with a row per scene and per skip, into
# build/bench/ when no --out is given (never into the committed results/bench/); a folder it cannot
# make is refused (exit 2) before anything is measured; its progress goes to a log as plain lines.
# No timing is checked. Usage: cli_bench_speed.sh path/to/footsim (run from the source folder).
. "$(dirname "$0")/cli_check.sh"
src=$PWD
case $fs in /*) ;; *) fs=$PWD/$fs ;; esac
# a checkout of its own: the shipped data through --data, the committed results folder beside it
mkdir -p "$tmp/co/results/bench" && cp "$src/results/bench/.footsim-results" "$tmp/co/results/bench/"
(cd "$tmp/co" && "$fs" bench speed --quick --data "$src" >/dev/null 2>"$tmp/err")
status=$?
check '[ "$status" -eq 0 ]'
check '[ -s "$tmp/co/build/bench/speed.csv" ] && [ -z "$(ls -A "$tmp/co/results/bench" | grep -v footsim-results)" ]'
mv "$tmp/co/build/bench" "$tmp/bench"
check '[ -z "$(tr -dc "\r" <"$tmp/err")" ]'
check 'grep -q "^footsim bench speed: [0-9]*/[0-9]* measurements done, 0 failed, " "$tmp/err"'
check 'grep -q "^bench speed: static_load: [0-9]* steps/s" "$tmp/err"'
check 'head -1 "$tmp/bench/speed.csv" | grep -q "^scene,runner," && tr -d " \t\n" <"$tmp/bench/speed.provenance.json" | grep -q "\"file\":\"speed.csv\",\"provenance\":{\"footsim\":.*\"inputs\":\[{\"path\":\"static_load.ini\",\"hash\":\"[0-9a-f]\{16\}\"}.*\"landing_trial.ini\".*\"seeds\":1,\"first_seed\":1}"'
for f in speed.csv skips.csv speed.md speed.gp; do
    check '[ -s "$tmp/bench/$f" ]'
done
if command -v gnuplot >/dev/null; then check '[ -s "$tmp/bench/speed.png" ]'; fi
check '[ -z "$(ls "$tmp/bench" | grep tmp)" ]'
check 'grep -q "^scene,runner,runs,steps,sim_s,step_s,wall_s,steps_per_s,rtf" "$tmp/bench/speed.csv"'
check '[ "$(grep -c "^static_load," "$tmp/bench/speed.csv")" -eq 1 ]'
check '[ "$(wc -l <"$tmp/bench/skips.csv")" -ge 6 ]'
check 'grep -q "\"machine\":[[:space:]]*\"[^\"]*cores online" "$tmp/bench/speed.provenance.json" && grep -q "\"file\":[[:space:]]*\"skips.csv\"" "$tmp/bench/skips.provenance.json"'
# both CSV files read right: one header row, rows as wide, a missing value an empty field (issue 32)
check '/usr/bin/python3 "$(dirname "$0")/csv_check.py" csv "$tmp/bench/speed.csv:steps_per_s" "$tmp/bench/skips.csv:with_s" >&2'
check '/usr/bin/python3 "$(dirname "$0")/csv_check.py" sqlite "$tmp/bench/speed.csv:steps_per_s" "$tmp/bench/skips.csv:with_s" >&2'
check 'grep -q "own code takes at most" "$tmp/bench/speed.md"'
# every scene row: each share a percentage; the ODE step takes some time in every scene;
# own_pct is the sum of its five stages (rounded to 0.1 each); steps = sim_s / step_s.
# (The three main shares summing to 100 % would be an identity: own is defined as the rest.)
check 'awk -F, "!/^#/ && \$1 != \"scene\" { for (i = 12; i <= 19; i++) if (\$i < 0 || \$i > 100) bad = 1;
    if (\$13 <= 0) bad = 1;
    o = \$15 + \$16 + \$17 + \$18 + \$19; if (o - \$14 > 0.3 || \$14 - o > 0.3) bad = 1;
    if (\$4 - \$5 / \$6 > 1.5 || \$5 / \$6 - \$4 > 1.5) bad = 1; n++ } END { exit bad || n < 5 }" "$tmp/bench/speed.csv"'
# a folder it cannot write: refused at once
touch "$tmp/file"
"$fs" bench speed --quick --out "$tmp/file/bench" >/dev/null 2>&1
status=$?
check '[ "$status" -eq 2 ]'
finish
