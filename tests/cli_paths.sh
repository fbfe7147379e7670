#!/bin/sh
# Issue 32: paths resolve as a user expects, from a folder outside the checkout. A path in --set is
# looked for from the current folder first (as a path on the command line is), then as before
# (relative to the file); a path inside a file stays relative to that file, then falls back to the
# data (--data, the current folder, the installed data); `stiffness` finds the shipped robots
# wherever the design lives; --help says the order. Usage: cli_paths.sh path/to/footsim (run from
# the source folder).
. "$(dirname "$0")/cli_check.sh"
src=$PWD
case $fs in /*) ;; *) fs=$PWD/$fs ;; esac
work="$tmp/work"
mkdir -p "$work/feet" "$work/sc"
cp "$src/scenarios/feet/biomimetic.ini" "$work/myfoot.ini"
# a design of the user's, named by --set from where they are: found here
(cd "$work" && "$fs" run static_load.ini --data "$src" --set scenario.design=myfoot.ini --set run.duration_s=0.01 \
    --out "$work/r1" >/dev/null 2>"$tmp/err")
check_that "--set scenario.design=myfoot.ini runs from the user's folder" [ $? -eq 0 ]
check_that "and the run read the user's file" grep -q '"path":[[:space:]]*"[^"]*/work/myfoot.ini"' "$work/r1/metrics.json"
# a file of the same relative name here and beside the scenario: --set's is the one here
cp "$src/scenarios/feet/flat.ini" "$work/feet/biomimetic.ini"
(cd "$work" && "$fs" run static_load.ini --data "$src" --set scenario.design=feet/biomimetic.ini \
    --set run.duration_s=0.01 --out "$work/r2" >/dev/null 2>&1)
check_that "--set feet/biomimetic.ini: the current folder's before the scenario's" \
    grep -q '"path":[[:space:]]*"[^"]*/work/feet/biomimetic.ini"' "$work/r2/metrics.json"
# not here: as before, relative to the scenario's folder (the shipped flat foot)
(cd "$work" && "$fs" run static_load.ini --data "$src" --set scenario.design=feet/flat.ini --set run.duration_s=0.01 \
    --out "$work/r3" >/dev/null 2>&1)
check_that "--set feet/flat.ini not here: the scenario's folder's" \
    grep -q '"path":[[:space:]]*"feet/flat.ini"' "$work/r3/metrics.json"
# inside a file: relative to the file, even when the current folder has a file of that name
cat >"$work/sc/mine.ini" <<EOF
[scenario]
design = own.ini
terrain = ../terrains/flat.ini
[run]
duration_s = 0.01
EOF
cp "$src/scenarios/feet/biomimetic.ini" "$work/sc/own.ini"
cp "$src/scenarios/feet/flat.ini" "$work/own.ini"
(cd "$work" && "$fs" run sc/mine.ini --data "$src" --out "$work/r4" >/dev/null 2>"$tmp/err")
check_that "a scenario of the user's runs, its terrain from the data (../terrains/flat.ini not beside it)" [ $? -eq 0 ]
check_that "its design the one beside it, not the current folder's" grep -q '"path":[[:space:]]*"own.ini"' "$work/r4/metrics.json"
check_that "its foot the biomimetic one" grep -q '"kind":[[:space:]]*"biomimetic"\|biomimetic' "$work/r4/metrics.json"
check_that "its terrain the shipped one" grep -q '"path":[[:space:]]*"[^"]*terrains/flat.ini"' "$work/r4/metrics.json"
# nowhere: refused (exit 2), the places looked in said
(cd "$work" && "$fs" run static_load.ini --data "$src" --set scenario.design=nothere.ini >/dev/null 2>"$tmp/err")
check_that "a --set path found nowhere: exit 2" [ $? -eq 2 ]
check_that "naming where it looked" grep -q "nothere.ini': no such file (looked for nothere.ini, then .*scenarios/nothere.ini)" "$tmp/err"
# stiffness of a design outside scenarios/feet/: the shipped robots' law all the same. Its d1 made
# progressive (k0 = Table I's, stiffness doubled at x0 = 0.02 mm), so the same run checks the line a
# nonlinear design adds: chain 3's K at the gripping equilibrium, eqs. 1-3 on each law's tangent there.
(cd "$work" && "$fs" stiffness myfoot.ini --data "$src" --set springs.d1_law=progressive --set springs.d1_x0_m=2e-5 \
    >"$tmp/stiff" 2>&1)
check_that "stiffness myfoot.ini gives the law for the shipped robots" sh -c "grep -q '^  single_tall ' '$tmp/stiff' && grep -q '^  drop_weight ' '$tmp/stiff'"
# d1 spans the midfoot joint alone and is the only nonlinear spring, so against the neutral chain 3
# the loaded K differs in K_midfoot,midfoot only, by k0 (x/x0)^2 G1^2 with x d1's printed deflection:
# more than 0 (d1 is stretched there), and at most (x/x0)^2 times the neutral K_mm (k0 G1^2 is one
# of its three nonnegative terms); the other entries equal to the printed digits
check_that "a nonlinear design: chain 3's K at the loaded pose, d1's tangent in its midfoot term" awk -v x0_mm=0.02 '
    /^  chain 3 / { c3 = 1 }
    c3 && /exact geometry/ { gsub(/[][;]/, " "); n00 = $3; n01 = $4; n11 = $6; c3 = 0 }
    /chain 3.s K at the gripping equilibrium/ {
        line = $0; sub(/.*deflected /, "", line); split(line, x, /[, ]+/)
        sub(/.*\[/, "", $0); gsub(/[];]/, " "); split($0, k, / +/); found = 1
    }
    END {
        d = k[2] - n00; r = (x[1] / x0_mm) ^ 2
        exit !(found && x[1] > 0 && d > 0 && d <= r * n00 + 1e-4 && k[3] == n01 && k[5] == n11)
    }' "$tmp/stiff"
# the order is said where users look
"$fs" run --help >"$tmp/help" 2>&1
check_that "--help says a --set path is looked for from the current folder first" grep -q 'current folder first' "$tmp/help"
finish cli_paths
