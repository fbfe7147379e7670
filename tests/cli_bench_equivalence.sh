#!/bin/sh
# footsim bench equivalence (docs/bench.md, "Campaign equivalence"): a tiny campaign (the flat foot
# under drop_weight on flat ground, 2 seeds) at a reference step and one step to judge writes
# equivalence.md with the step's row, h<STEP>.md and the reference campaign's files, exit 0, and
# leaves no scratch behind; a bad step is refused (exit 2) before anything is written; a folder of
# the user's is refused without --replace and kept with it; a run again into its own folder
# replaces its files, and a run at other steps removes the earlier steps' comparisons.
# Usage: cli_bench_equivalence.sh path/to/footsim (run from the source folder).
. "$(dirname "$0")/cli_check.sh"
src=$PWD
cat >"$tmp/tiny.ini" <<END
[campaign]
trial = $src/scenarios/landing_trial.ini
seeds = 2

[foot.flat]
file = $src/scenarios/feet/flat.ini

[robot.drop_weight]
file = $src/scenarios/robots/drop_weight.ini

[terrain.flat]
file = $src/terrains/flat.ini
END
eq() { "$fs" bench equivalence "$tmp/tiny.ini" --reference 1e-4 "$@"; }
eq --steps 1e-3 --out "$tmp/eq" >"$tmp/out" 2>"$tmp/err"
status=$?
check '[ "$status" -eq 0 ]'
md="$tmp/eq/equivalence.md"
check 'head -1 "$md" | grep -q "^# Campaign equivalence: .*tiny.ini"'
check 'grep -q "; 1 worker (-j 1). Reference: h = 1e-4 s, [0-9.e+-]* s of wall time" "$md"'
# one row, the step's: its verdict, a count, the wall time and the speed-up
check '[ "$(grep -c "^| [0-9]" "$md")" -eq 1 ]'
check 'grep -Eq "^\| 1e-3 \| (equivalent|\*\*not equivalent\*\*) \| [0-9]+ \| [0-9.e+-]+ \| [0-9.]+ \|$" "$md"'
check 'grep -q "^Provenance (of the reference): footsim .*; seeds 1 to 2; .*overrides .run.step_s=1e-4.\.$" "$md"'
# the comparison, judged against the reference put in place
check 'grep -q "^The campaign at h = 1e-3 s against the reference $tmp/eq/reference/summary.json" "$tmp/eq/h1e-3.md"'
# the count of the row is the comparison's own
n=$(grep -c "\*\*differs\*\*" "$tmp/eq/h1e-3.md")
check 'grep -q "^| 1e-3 | [^|]* | $n |" "$md"'
check 'grep -q "^| flat | flat | drop_weight | median_rest_ankle_drop_m |" "$tmp/eq/h1e-3.md"'
for f in summary.json summary.md summary.csv trials.csv; do
    check '[ -s "$tmp/eq/reference/$f" ]'
done
check 'grep -q "\"run.step_s=1e-4\"" "$tmp/eq/reference/summary.json"'
# the table on stdout too; no scratch folder or lock left
check 'grep -q "^| 1e-3 | " "$tmp/out"'
check '[ -z "$(ls -A "$tmp/eq" | grep -v -e "^equivalence.md$" -e "^h1e-3.md$" -e "^reference$" -e "^.footsim-results$")" ]'
check '[ -z "$(ls -A "$tmp" | grep -e partial -e lock)" ]'
# bad steps: exit 2, what is wrong and what would be right, nothing made
expect 2 "--steps: 'abc' is not a number of seconds; give steps separated by commas" -- bench equivalence "$tmp/tiny.ini" --steps abc --out "$tmp/bad"
expect 2 "--steps: '1' is out of range; give .* from 1e-07 to 0.1" -- bench equivalence "$tmp/tiny.ini" --steps 1e-3,1 --out "$tmp/bad"
expect 2 "--reference: 'x' is not a number of seconds" -- bench equivalence "$tmp/tiny.ini" --reference x --out "$tmp/bad"
expect 2 "cannot open" -- bench equivalence "$tmp/missing.ini" --steps 1e-3 --out "$tmp/bad"
check '[ ! -e "$tmp/bad" ]'
# a folder of the user's: refused before any trial, kept; with --replace written into, the user's file kept
mkdir "$tmp/mine" && echo notes >"$tmp/mine/notes.txt"
expect 2 "a folder footsim did not make" -- bench equivalence "$tmp/tiny.ini" --steps 1e-3 --out "$tmp/mine"
check '[ "$(ls -A "$tmp/mine")" = notes.txt ]'
eq --steps 1e-3 --out "$tmp/mine" --replace >/dev/null 2>&1
status=$?
check '[ "$status" -eq 0 ] && [ -s "$tmp/mine/equivalence.md" ] && [ "$(cat "$tmp/mine/notes.txt")" = notes ]'
# again into its own folder: its files replaced, each whole (the step's file stays, the row the new run's)
touch -d "2000-01-01" "$md" "$tmp/eq/h1e-3.md"
eq --steps 1e-3 --out "$tmp/eq" -j 2 >/dev/null 2>"$tmp/err2"
status=$?
check '[ "$status" -eq 0 ] && [ -n "$(find "$md" "$tmp/eq/h1e-3.md" -newermt 2001-01-01)" ]'
check '[ "$(find "$md" "$tmp/eq/h1e-3.md" -newermt 2001-01-01 | wc -l)" -eq 2 ]'
check 'grep -q "; 2 workers (-j 2)" "$md" && [ "$(grep -c "^| 1e-3 | " "$md")" -eq 1 ]'
check '[ -z "$(ls -A "$tmp" | grep -e partial -e lock)" ]'
# another step: the earlier step's comparison goes (said on stderr), a file not named for a step stays
echo notes >"$tmp/eq/hello.md"
eq --steps 2e-3 --out "$tmp/eq" >/dev/null 2>"$tmp/err3"
status=$?
check '[ "$status" -eq 0 ] && [ -s "$tmp/eq/h2e-3.md" ] && [ ! -e "$tmp/eq/h1e-3.md" ] && [ -s "$tmp/eq/hello.md" ]'
check 'grep -q "removed $tmp/eq/h1e-3.md, a comparison from an earlier run at another step" "$tmp/err3"'
check '[ "$(grep -c "^| [0-9]" "$md")" -eq 1 ] && grep -q "^| 2e-3 | " "$md"'
finish
