#!/bin/sh
# footsim bench precision --quick writes its table, summary and chart, marks each scene's default
# and Pareto front, and ODE's error on the pinned chain falls as the step does (first order: ten
# times smaller step, about ten times smaller error); its campaign-equivalence stage writes its
# verdicts. Usage: cli_bench_precision.sh path/to/footsim
. "$(dirname "$0")/cli_check.sh"
"$fs" bench precision --quick --out "$tmp/bench" >/dev/null 2>"$tmp/err.txt"
status=$?
check '[ "$status" -eq 0 ]'
csv="$tmp/bench/precision.csv" eq_ref="$tmp/bench/precision_equivalence/reference"
# the header first; what made it beside it (the scenarios' files with their hashes, relative to scenarios/)
check 'tr -d " \t\n" <"$tmp/bench/precision.provenance.json" | grep -q "\"file\":\"precision.csv\",\"provenance\":{\"footsim\":\"[^\"]*\",\"overrides\":\[\],\"inputs\":\[{\"path\":\"static_load.ini\",\"hash\":\"[0-9a-f]\{16\}\"}.*\"landing_trial.ini\".*\"../terrains/rough.ini\""'
check 'head -1 "$csv" | grep -q "^scene,stepper,iterations,spring,step_s,max_err_m,rms_err_m,.*,rtf,status,pareto,default,impact_substeps,tolerance_m,steps,rejected,ode_steps,sinkage_m,sinkage_err_m,error_estimate$"'
# no scene of the quick sweep is on a soil: its sinkage columns are empty (missing, not 0)
check '[ "$(awk -F, "NR > 1 && (\$21 != \"\" || \$22 != \"\")" "$csv" | wc -l)" -eq 0 ]'
# read right: one header row, rows as wide, a blown-up run's error an empty field (issue 32)
check '/usr/bin/python3 "$(dirname "$0")/csv_check.py" csv "$csv:max_err_m" "$eq_ref/trials.csv:steps" >&2'
check '/usr/bin/python3 "$(dirname "$0")/csv_check.py" sqlite "$csv:max_err_m" "$eq_ref/summary.csv:trials" >&2'
# 3 steps x 2 steppers: x 2 spring implementations for the chain and the two biomimetic landings, x 1 for the flat
# foot (42); each landing at 1e-3 and 1e-2 s with its touchdown in 8 substeps (6); each landing with an
# error-controlled step at 1e-5 m under each error estimate, step doubling and the embedded pair (6)
check '[ "$(tail -n +2 "$csv" | wc -l)" -eq 54 ]'
# the estimate named on the tolerance rows alone, each estimate on each landing once
check '[ "$(awk -F, "NR > 1 && (\$17 > 0) != (\$23 != \"\")" "$csv" | wc -l)" -eq 0 ]'
check '[ "$(awk -F, "\$23 == \"doubling\"" "$csv" | wc -l)" -eq 3 ] && [ "$(awk -F, "\$23 == \"embedded\"" "$csv" | wc -l)" -eq 3 ]'
check '[ "$(awk -F, "\$16 == 8" "$csv" | wc -l)" -eq 6 ]'
check '[ "$(awk -F, "\$1 == \"chain\" && \$16 != 1" "$csv" | wc -l)" -eq 0 ]'
check 'grep -q "^Provenance: footsim " "$tmp/bench/precision.md"'
# progress without a terminal: plain lines with done/total, never a carriage return
check '[ -z "$(tr -dc "\r" <"$tmp/err.txt")" ]'
check 'grep -q "^footsim bench precision: 54/54 configurations done, [0-9]* failed, .* s elapsed" "$tmp/err.txt"'
check '[ "$(grep -c "configurations done" "$tmp/err.txt")" -le 12 ]'
for scene in chain landing_flat landing_biomimetic landing_biomimetic_rough; do
  check '[ "$(awk -F, -v s=$scene "\$1 == s && \$15 == 1" "$csv" | wc -l)" -eq 1 ]'
  check '[ "$(awk -F, -v s=$scene "\$1 == s && \$14 == 1" "$csv" | wc -l)" -ge 1 ]'
done
ratio=$(awk -F, '$1 == "chain" && $2 == "step" && $4 == "implicit" && $5 == 0.001 { a = $6 }
                 $1 == "chain" && $2 == "step" && $4 == "implicit" && $5 == 0.0001 { b = $6 }
                 END { print a / b }' "$csv")
check 'awk -v r="$ratio" "BEGIN { exit !(r > 5 && r < 20) }"'
# a step of 1e-2 s falls 3 mm a step at touchdown and does not resolve the impact; in substeps of an
# eighth it does, so the biomimetic landing's largest error (at touchdown: docs/bench.md) must fall,
# by much more than half (first order: an eighth, were the error all at the impact)
ratio=$(awk -F, '$1 == "landing_biomimetic" && $2 == "step" && $4 == "implicit" && $5 == 0.01 && $16 == 1 { a = $6 }
                 $1 == "landing_biomimetic" && $5 == 0.01 && $16 == 8 { b = $6 }
                 END { print b / a }' "$csv")
check 'awk -v r="$ratio" "BEGIN { exit !(r < 0.5) }"'
# the error-controlled step: each landing's row ran (its touchdown rejected a step at least) and took
# fewer than half the ODE steps of the fixed default (the point of it: docs/bench.md); the embedded
# pair takes fewer ODE steps than doubling (a step of doubling is three ODE steps, of the pair two)
for scene in landing_flat landing_biomimetic landing_biomimetic_rough; do
  for est in doubling embedded; do
    check 'awk -F, -v s=$scene -v e=$est "\$1 == s && \$15 == 1 { d = \$20 } \$1 == s && \$17 == 1e-05 && \$23 == e { n++; ok = \$13 == \"ok\" && \$19 >= 1; t = \$20 }
           END { exit !(n == 1 && ok && t < d / 2) }" "$csv"'
  done
  check 'awk -F, -v s=$scene "\$1 == s && \$23 == \"doubling\" { d = \$20 } \$1 == s && \$23 == \"embedded\" { e = \$20 }
         END { exit !(e > 0 && e < d) }" "$csv"'
done
check 'grep -q "Goal" "$tmp/bench/precision.md"'
# the campaign-equivalence stage (--quick: equivalence_flat.ini on 2 seeds against 5e-5 s at 1e-4 and
# 1e-3 s): its files, a row per step with its verdict in its folder and in precision.md
eq="$tmp/bench/precision_equivalence"
for f in equivalence.md h1e-4.md h1e-3.md reference/summary.json reference/summary.md reference/summary.csv \
         reference/trials.csv; do
  check '[ -s "$eq/$f" ]'
done
check 'grep -q "^\`footsim bench precision --quick\` on .*; 1 worker (-j 1). Reference: h = 5e-5 s" "$eq/equivalence.md"'
for md in "$eq/equivalence.md" "$tmp/bench/precision.md"; do
  check '[ "$(grep -c "^| [0-9]" "$md")" -eq 2 ]'
  check 'grep -Eq "^\| 1e-4 \| (equivalent|\*\*not equivalent\*\*) \| [0-9]+ \| " "$md"'
  check 'grep -Eq "^\| 1e-3 \| (equivalent|\*\*not equivalent\*\*) \| [0-9]+ \| " "$md"'
done
check 'grep -q "^### Campaign equivalence" "$tmp/bench/precision.md"'
check 'grep -q "against the reference $tmp/bench/precision_equivalence/reference/summary.json" "$eq/h1e-3.md"'
check '[ -z "$(ls -A "$eq" | grep -e partial -e lock)" ]'
if command -v gnuplot >/dev/null 2>&1; then check '[ -s "$tmp/bench/precision.png" ]'; fi
# --scene: only the scenes named, their rows alone, and no campaign-equivalence stage (said in the .md)
"$fs" bench precision --quick --scene chain --out "$tmp/chain" >/dev/null 2>"$tmp/err.txt"
status=$?
check '[ "$status" -eq 0 ]'
check '[ "$(tail -n +2 "$tmp/chain/precision.csv" | wc -l)" -eq 12 ]'
check '[ "$(tail -n +2 "$tmp/chain/precision.csv" | cut -d, -f1 | sort -u)" = chain ]'
check '[ ! -e "$tmp/chain/precision_equivalence" ]'
check 'grep -q "^### chain: the Pareto front" "$tmp/chain/precision.md"'
check '! grep -q "^### landing" "$tmp/chain/precision.md"'
check 'grep -q "^Not run: .--scene. named" "$tmp/chain/precision.md"'
check 'grep -q "no campaign-equivalence stage" "$tmp/err.txt"'
# an unknown scene (or an empty name) is refused before anything runs, the names listed
for bad in nonsense chain,; do
  "$fs" bench precision --quick --scene "$bad" --out "$tmp/bad" >/dev/null 2>"$tmp/err.txt"
  status=$?
  check '[ "$status" -eq 2 ]'
  check 'grep -q "give one or more of chain, landing_flat, .*, flat_rig_dry_sand" "$tmp/err.txt"'
  check '[ ! -e "$tmp/bad" ]'
done
"$fs" bench speed --scene chain --out "$tmp/bad" >/dev/null 2>&1
status=$?
check '[ "$status" -eq 2 ]'
# bench stability --scene: only the named slice runs (1 K_e x 5 steps x 4 stepper-springs with
# --quick), and only its table and chart are written; an unknown slice refused before anything runs
"$fs" bench stability --quick --scene soil -j 1 --out "$tmp/soil" >/dev/null 2>&1
status=$?
check '[ "$status" -eq 0 ]'
check '[ "$(tail -n +2 "$tmp/soil/stability.csv" | wc -l)" -eq 20 ]'
check '[ "$(tail -n +2 "$tmp/soil/stability.csv" | cut -d, -f1 | sort -u)" = soil ]'
check 'grep -q "^# Numerical stability (.footsim bench stability --quick --scene soil.)" "$tmp/soil/stability.md"'
check 'grep -q "^### soil: " "$tmp/soil/stability.md"'
check '! grep -q "^### stiffness" "$tmp/soil/stability.md"'
check '[ "$(cd "$tmp/soil" && ls stability_*.gp)" = stability_soil.gp ]'
# the script's first line names how to run it: itself, from its folder
check 'head -1 "$tmp/soil/stability_soil.gp" | grep -q "gnuplot -e \"out=.x.png.\" stability_soil.gp)$"'
"$fs" bench stability --scene soil,sand --out "$tmp/bad" >/dev/null 2>"$tmp/err.txt"
status=$?
check '[ "$status" -eq 2 ]'
check 'grep -q "no slice is called .sand.; give one or more of stiffness, load, mass, drop, soil, law" "$tmp/err.txt"'
check '[ ! -e "$tmp/bad" ]'
"$fs" bench nonsense 2>/dev/null
status=$?
check '[ "$status" -eq 2 ]'
# an unknown benchmark is named as such, whatever else is given
"$fs" bench nonsense --scene chain 2>"$tmp/err.txt"
status=$?
check '[ "$status" -eq 2 ]'
check 'grep -q "unknown benchmark .nonsense." "$tmp/err.txt"'
finish
