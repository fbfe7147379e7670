#!/bin/sh
# footsim bench precision --quick writes its table, summary and chart, marks each scene's default
# and Pareto front, and ODE's error on the pinned chain falls as the step does (first order: ten
# times smaller step, about ten times smaller error). Usage: cli_bench_precision.sh path/to/footsim
. "$(dirname "$0")/cli_check.sh"
"$fs" bench precision --quick --out "$tmp/bench" >/dev/null 2>"$tmp/err.txt"
status=$?
check '[ "$status" -eq 0 ]'
csv="$tmp/bench/precision.csv"
# what made it first (the scenarios' files with their hashes, relative to scenarios/), then the header
check 'head -1 "$csv" | grep -q "^# provenance: footsim .*; inputs static_load.ini=[0-9a-f]\{16\} .*landing_trial.ini=.*../terrains/rough.ini=.*; overrides none$"'
check 'sed -n 2p "$csv" | grep -q "^scene,stepper,iterations,spring,step_s,max_err_m,rms_err_m,.*,rtf,status,pareto,default$"'
# 3 steps x 2 steppers: x 2 spring implementations for the chain and the two biomimetic landings, x 1 for the flat foot
check '[ "$(tail -n +3 "$csv" | wc -l)" -eq 42 ]'
check 'grep -q "^Provenance: footsim " "$tmp/bench/precision.md"'
# progress without a terminal: plain lines with done/total, never a carriage return
check '[ -z "$(tr -dc "\r" <"$tmp/err.txt")" ]'
check 'grep -q "^footsim bench precision: 42/42 configurations done, [0-9]* failed, .* s elapsed" "$tmp/err.txt"'
check '[ "$(grep -c "configurations done" "$tmp/err.txt")" -le 12 ]'
for scene in chain landing_flat landing_biomimetic landing_biomimetic_rough; do
  check '[ "$(awk -F, -v s=$scene "\$1 == s && \$15 == 1" "$csv" | wc -l)" -eq 1 ]'
  check '[ "$(awk -F, -v s=$scene "\$1 == s && \$14 == 1" "$csv" | wc -l)" -ge 1 ]'
done
ratio=$(awk -F, '$1 == "chain" && $2 == "step" && $4 == "implicit" && $5 == 0.001 { a = $6 }
                 $1 == "chain" && $2 == "step" && $4 == "implicit" && $5 == 0.0001 { b = $6 }
                 END { print a / b }' "$csv")
check 'awk -v r="$ratio" "BEGIN { exit !(r > 5 && r < 20) }"'
check 'grep -q "Goal" "$tmp/bench/precision.md"'
if command -v gnuplot >/dev/null 2>&1; then check '[ -s "$tmp/bench/precision.png" ]'; fi
"$fs" bench nonsense 2>/dev/null
status=$?
check '[ "$status" -eq 2 ]'
finish
