#!/bin/sh
# A run that blows up exits 3, says which body (or hinge), when and what to try, and writes nothing: no results
# folder, no partial folder, and an earlier run's results left as they were; a trial exits 3 too.
# Usage: cli_numerical.sh path/to/footsim (run from the source folder).
. "$(dirname "$0")/cli_check.sh"
# explicit springs at 1 ms, 25 times beyond their 4e-5 s limit
blow="--set run.springs=explicit --set run.step_s=1e-3"
"$fs" run scenarios/static_load.ini $blow --out "$tmp/new" >"$tmp/out.txt" 2>"$tmp/err.txt"
status=$?
check '[ "$status" -eq 3 ]'
check '[ ! -e "$tmp/new" ]'
check '[ -z "$(ls -d "$tmp"/new.partial.* 2>/dev/null)" ]'
check 'grep -q "t = .* \(body\|hinge\) " "$tmp/err.txt"'
check 'grep -q "run.step_s" "$tmp/err.txt" && grep -q "run.springs = implicit" "$tmp/err.txt"'
check '[ ! -s "$tmp/out.txt" ]'
# into a folder with results: they stay
"$fs" run scenarios/static_load.ini --set run.duration_s=0.05 --out "$tmp/old" >/dev/null
cp "$tmp/old/metrics.json" "$tmp/before.json"
"$fs" run scenarios/static_load.ini $blow --out "$tmp/old" 2>/dev/null
status=$?
check '[ "$status" -eq 3 ]'
check 'cmp -s "$tmp/before.json" "$tmp/old/metrics.json"'
check '[ -z "$(ls -d "$tmp"/old.partial.* 2>/dev/null)" ]'
# a trial that blows up: exit 3 as well
"$fs" trial scenarios/landing_trial.ini $blow >/dev/null 2>&1
status=$?
check '[ "$status" -eq 3 ]'
finish
