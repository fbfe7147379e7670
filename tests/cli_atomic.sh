#!/bin/sh
# A run's folder is replaced whole: a second run into it leaves exactly the new run's files, and no
# partial folder behind; a file-size limit reached while writing leaves the old folder, exit 4. Usage: cli_atomic.sh path/to/footsim (run from the source folder).
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
# issue 33 item 5: a file-size limit (ulimit -f) is a write error, not SIGXFSZ's silent death: exit 4,
# the file named where it was to be, no partial folder and no lock left; an earlier result stays
for cmd in "run scenarios/static_load.ini" "trial scenarios/landing_trial.ini"; do
    (ulimit -f 20 && exec "$fs" $cmd --out "$tmp/lim") >/dev/null 2>"$tmp/lim.err"
    status=$?
    check '[ "$status" -eq 4 ] && grep -q "lim/trajectory.csv: cannot write: File too large (a file-size limit, ulimit -f" "$tmp/lim.err"'
    check '[ ! -e "$tmp/lim" ] && [ -z "$(ls -a "$tmp" | grep -e "lim\.partial" -e "\.lim\.footsim-lock")" ]'
done
(ulimit -f 20 && exec "$fs" run scenarios/static_load.ini --out "$tmp/out") >/dev/null 2>/dev/null
status=$?
check '[ "$status" -eq 4 ] && cmp -s "$tmp/before.json" "$tmp/out/metrics.json" && [ -z "$(ls -a "$tmp" | grep -e partial -e lock)" ]'
finish
