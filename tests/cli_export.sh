#!/bin/sh
# footsim export --mjcf from the command line: bad input refused with exit 2 and nothing written,
# the XML and its heightfield file written where asked (or under results/export/), an existing
# export replaced whole, a file footsim did not export kept unless --replace, --data honoured, the
# XML well-formed. What the XML holds is
# test_export_mjcf's and test_export_mujoco's. Usage: cli_export.sh path/to/footsim.
. "$(dirname "$0")/cli_check.sh"
src=$(pwd)
expect 2 "give the format, --mjcf" -- export scenarios/feet/biomimetic.ini --out "$tmp/a.xml"
expect 2 "is a folder" -- export --mjcf scenarios/feet/biomimetic.ini --out "$tmp"
expect 2 "give a path in an existing folder" -- export --mjcf scenarios/feet/biomimetic.ini --out "$tmp/no/a.xml"
expect 2 "k_d1_N_per_m" -- export --mjcf scenarios/feet/biomimetic.ini --set springs.k_d1_N_per_m=-5 --out "$tmp/a.xml"
expect 2 "nope.ini" -- export --mjcf scenarios/feet/biomimetic.ini --scenario nope.ini --out "$tmp/a.xml"
check '[ ! -e "$tmp/a.xml" ]'
# written, with its heightfield beside; written again over itself
check '"$fs" export --mjcf scenarios/feet/biomimetic.ini --scenario scenarios/walking.ini --out "$tmp/w.xml" >"$tmp/out"'
check '[ -s "$tmp/w.xml" ] && [ -s "$tmp/w.hfield.bin" ] && grep -q "w.hfield.bin" "$tmp/out"'
check '"$fs" export --mjcf scenarios/feet/biomimetic.ini --scenario scenarios/walking.ini --out "$tmp/w.xml" >"$tmp/out"'
# a file footsim did not export is not replaced without --replace
echo "my notes" >"$tmp/notes.xml"
expect 2 "is not an MJCF file footsim exported" -- export --mjcf scenarios/feet/biomimetic.ini --out "$tmp/notes.xml"
check '[ "$(cat "$tmp/notes.xml")" = "my notes" ]'
check '"$fs" export --mjcf scenarios/feet/biomimetic.ini --out "$tmp/notes.xml" --replace >/dev/null && grep -q "<mujoco" "$tmp/notes.xml"'
check 'grep -q "file=\"w.hfield.bin\"" "$tmp/w.xml" && [ -z "$(ls "$tmp" | grep "\.tmp\.")" ]'
# by data name from another folder: the default path under the current folder
mkdir "$tmp/work"
(cd "$tmp/work" && "$fs" export --mjcf biomimetic.ini --data "$src" >/dev/null)
check '[ -s "$tmp/work/results/export/biomimetic.xml" ]'
if command -v xmllint >/dev/null; then
    check 'xmllint --noout "$tmp/w.xml" "$tmp/work/results/export/biomimetic.xml"'
else
    echo "cli_export: no xmllint (Debian libxml2-utils); well-formedness is test_export_mjcf's" >&2
fi
# --seed N: the trial's drawn start (tools/mujoco_trial.c runs it); each seed its own pose
check '"$fs" export --mjcf scenarios/feet/biomimetic.ini --scenario scenarios/landing_trial.ini --out "$tmp/t0.xml" >/dev/null'
check '"$fs" export --mjcf scenarios/feet/biomimetic.ini --scenario scenarios/landing_trial.ini --seed 1 --out "$tmp/t1.xml" >/dev/null'
check '"$fs" export --mjcf scenarios/feet/biomimetic.ini --scenario scenarios/landing_trial.ini --seed 2 --out "$tmp/t2.xml" >/dev/null'
check '! cmp -s "$tmp/t0.xml" "$tmp/t1.xml" && ! cmp -s "$tmp/t1.xml" "$tmp/t2.xml"'
expect 2 "give a trial scenario with --scenario" -- export --mjcf scenarios/feet/biomimetic.ini --seed 1 --out "$tmp/s.xml"
expect 2 "whole number" -- export --mjcf scenarios/feet/biomimetic.ini --scenario scenarios/landing_trial.ini --seed x --out "$tmp/s.xml"
expect 2 "trial" -- export --mjcf scenarios/feet/biomimetic.ini --scenario scenarios/static_load.ini --seed 1 --out "$tmp/s.xml"
check '[ ! -e "$tmp/s.xml" ]'
check '"$fs" export --help | grep -q -- "export DESIGN --mjcf \[--scenario SCENARIO\] \[--out FILE\] \[--replace\]"'
finish
