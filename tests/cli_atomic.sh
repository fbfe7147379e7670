#!/bin/sh
# A run's folder is replaced whole: a second run into it leaves exactly the new run's files, and no
# partial folder behind. Usage: cli_atomic.sh path/to/footsim (run from the source folder).
. "$(dirname "$0")/cli_check.sh"
"$fs" run scenarios/static_load.ini --set run.duration_s=0.05 --out "$tmp/out" >/dev/null
check '[ -f "$tmp/out/.footsim-results" ]'
echo stale >"$tmp/out/old.txt" # a folder footsim made (its marker) is replaced whole, whatever it holds
"$fs" run scenarios/static_load.ini --set run.duration_s=0.05 --out "$tmp/out" >/dev/null
check '[ -f "$tmp/out/metrics.json" ] && [ -f "$tmp/out/trajectory.csv" ]'
check '[ ! -e "$tmp/out/old.txt" ]'
check '[ -z "$(ls -d "$tmp"/out.partial.* "$tmp"/.out.footsim-lock 2>/dev/null)" ]'
# a refused run leaves the previous results as they were
cp "$tmp/out/metrics.json" "$tmp/before.json"
"$fs" run scenarios/static_load.ini --set load.mass_kg=-1 --out "$tmp/out" 2>/dev/null
status=$?
check '[ "$status" -eq 2 ]'
check 'cmp -s "$tmp/before.json" "$tmp/out/metrics.json"'
finish
