#!/bin/sh
# The footsim command refuses bad input with "file:line: ..." on stderr and exit status 2, and
# writes nothing. Usage: cli_bad_input.sh path/to/footsim (run from the source folder).
fs=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0 failed=0

# expect STATUS PATTERN -- ARGS...: exit status and a pattern that stderr must contain
expect() {
    want=$1 pattern=$2
    shift 3
    "$fs" "$@" >"$tmp/out" 2>"$tmp/err"
    got=$?
    if [ "$got" -eq "$want" ] && grep -q -- "$pattern" "$tmp/err"; then
        passed=$((passed + 1))
    else
        failed=$((failed + 1))
        echo "FAIL: footsim $* gave status $got (wanted $want); stderr:" >&2
        cat "$tmp/err" >&2
        echo "  (wanted it to contain: $pattern)" >&2
    fi
}

printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[load]\nmass_kg = -26\n' "$PWD" >"$tmp/neg.ini"
printf '[scenario]\ndesign = nowhere.ini\n' >"$tmp/nodesign.ini"
printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[run]\nstep_s = 1e-4\nstep_s = 1e-3\n' "$PWD" >"$tmp/dup.ini"

expect 2 "$tmp/neg.ini:4: mass_kg = '-26' is out of range" -- run "$tmp/neg.ini" --out "$tmp/o1"
expect 2 "$tmp/nodesign.ini:2: design = 'nowhere.ini': no such file" -- run "$tmp/nodesign.ini" --out "$tmp/o2"
expect 2 "$tmp/dup.ini:5: \[run\] step_s is given twice" -- run "$tmp/dup.ini" --out "$tmp/o3"
expect 2 "missing.ini: No such file" -- run missing.ini --out "$tmp/o4"
expect 2 "--set springs.k_d2_N_per_m: k_d2_N_per_m = '0' is out of range" -- run scenarios/static_load.ini --set springs.k_d2_N_per_m=0 --out "$tmp/o5"
expect 2 "unknown option --frobnicate" -- run scenarios/static_load.ini --frobnicate
expect 2 "give a SCENARIO file" -- run
expect 2 "unknown command" -- sprint
expect 2 "cannot create folder" -- run scenarios/static_load.ini --out /proc/footsim/out
expect 2 "unknown section \[wheels\]" -- stiffness scenarios/feet/biomimetic.ini --set wheels.count=4

# nothing was written for any refused run
for d in o1 o2 o3 o4 o5; do
    if [ -e "$tmp/$d" ]; then failed=$((failed + 1)); echo "FAIL: $tmp/$d was created" >&2; else passed=$((passed + 1)); fi
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
