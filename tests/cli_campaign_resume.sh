#!/bin/sh
# footsim campaign survives interruption (issue 13 §1): a campaign killed (SIGKILL, at chosen
# points through FOOTSIM_TEST_SIGNAL_AFTER, and again during its resume) or stopped (SIGINT,
# SIGTERM) and then run again finishes with files byte for byte those of an uninterrupted run; a
# stop says how many trials are done and the command that continues, exit 130/143; a journal of
# other inputs is refused (exit 2, naming --fresh) and kept; a comment edit is not another input;
# a torn last record runs again; a finished folder is left alone; --fresh starts over.
# Usage: cli_campaign_resume.sh path/to/footsim (run from the source folder).
fs=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0 failed=0

check() { # check DESCRIPTION COMMAND...: the command must succeed
    what=$1
    shift
    if "$@"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $what" >&2; fi
}

. tests/small_campaign.sh
same_as_ref() { # same_as_ref DIR WHAT
    for f in $files; do
        check "$2: $f byte for byte an uninterrupted run's" cmp -s "$tmp/ref/$f" "$1/$f"
    done
    check "$2: the journal is removed" [ ! -e "$1.journal" ]
    check "$2: no partial folder or lock left" [ -z "$(ls -a "$tmp" | grep -e '\.partial\.' -e 'footsim-lock')" ]
}

camp -j 2 --out "$tmp/ref" >/dev/null 2>&1
check "the uninterrupted run exits 0" [ $? -eq 0 ]
check "it leaves no journal" [ ! -e "$tmp/ref.journal" ]

# SIGKILL after 1 trial, then resumed on another number of workers
FOOTSIM_TEST_SIGNAL_AFTER="1 9" camp -j 2 --out "$tmp/k1" >/dev/null 2>&1
check "SIGKILL: exit 137" [ $? -eq 137 ]
check "SIGKILL: the journal holds the trial" [ "$(grep -c '^[0-9]* [0-9]* ' "$tmp/k1.journal/journal")" -eq 1 ]
check "SIGKILL: no results folder yet" [ ! -e "$tmp/k1" ]
camp -j 1 --out "$tmp/k1" >/dev/null 2>"$tmp/k1.err"
check "resumed after SIGKILL: exit 0" [ $? -eq 0 ]
check "resumed: said so" grep -q 'resuming from .*k1.journal/journal: 1 of 6 trials done, 5 to run' "$tmp/k1.err"
same_as_ref "$tmp/k1" "resumed after a SIGKILL at 1"

# SIGKILL after 4 trials, SIGKILL again 1 trial into the resume, then resumed
FOOTSIM_TEST_SIGNAL_AFTER="4 9" camp -j 2 --out "$tmp/k4" >/dev/null 2>&1
FOOTSIM_TEST_SIGNAL_AFTER="1 9" camp -j 2 --out "$tmp/k4" >/dev/null 2>&1
check "killed twice: the journal holds 5 trials" [ "$(grep -c '^[0-9]* [0-9]* ' "$tmp/k4.journal/journal")" -eq 5 ]
camp -j 2 --out "$tmp/k4" >/dev/null 2>&1
check "resumed after two kills: exit 0" [ $? -eq 0 ]
same_as_ref "$tmp/k4" "resumed after SIGKILLs at 4 and 5"

# a record cut short by a kill in the middle of its write: ignored, its trial runs again
FOOTSIM_TEST_SIGNAL_AFTER="2 9" camp -j 2 --out "$tmp/torn" >/dev/null 2>&1
printf '5 3 0 6 1500 0x1.8p' >>"$tmp/torn.journal/journal"
camp -j 2 --out "$tmp/torn" >/dev/null 2>"$tmp/torn.err"
check "a torn last record: exit 0" [ $? -eq 0 ]
check "a torn last record: not counted" grep -q '2 of 6 trials done, 4 to run' "$tmp/torn.err"
same_as_ref "$tmp/torn" "resumed after a torn record"

# SIGINT after 2 trials: one line with the count and the command, exit 130; that command finishes
FOOTSIM_TEST_SIGNAL_AFTER="2 2" camp -j 2 --out "$tmp/int" >/dev/null 2>"$tmp/int.err"
check "SIGINT: exit 130" [ $? -eq 130 ]
check "SIGINT: one line with the trials done and where they are" \
    grep -q "^footsim campaign: stopped by SIGINT: 2 of 6 trials done, kept in $tmp/int.journal/; to continue: footsim campaign " "$tmp/int.err"
check "SIGINT: no worker left" [ -z "$(ps -eo args= | grep -F "$tmp/small.ini" | grep -v grep)" ]
check "SIGINT: no results folder" [ ! -e "$tmp/int" ]
check "SIGINT: no partial folder" [ -z "$(ls "$tmp" | grep '\.partial\.')" ]
again=$(sed -n 's/^footsim campaign: stopped by SIGINT: .*; to continue: footsim //p' "$tmp/int.err")
check "SIGINT: the command names the overrides" [ -n "$(echo "$again" | grep -e '--set run.duration_s=0.15')" ]
eval "nice \"\$fs\" $again" >/dev/null 2>"$tmp/int2.err"
check "the printed command finishes it: exit 0" [ $? -eq 0 ]
check "the printed command resumed" grep -q '2 of 6 trials done, 4 to run' "$tmp/int2.err"
same_as_ref "$tmp/int" "resumed after SIGINT"

# SIGTERM from outside, while the trials run: exit 143, the journal kept
(exec nice "$fs" campaign "$tmp/small.ini" --set run.duration_s=0.15 -j 2 --out "$tmp/term" >/dev/null 2>"$tmp/term.err") &
pid=$!
n=0
until grep -q '^[0-9]* [0-9]* ' "$tmp/term.journal/journal" 2>/dev/null || [ $n -ge 600 ]; do sleep 0.05; n=$((n + 1)); done
kill -TERM $pid
wait $pid
check "SIGTERM: exit 143" [ $? -eq 143 ]
check "SIGTERM: said so" grep -q '^footsim campaign: stopped by SIGTERM: [0-9] of 6 trials done' "$tmp/term.err"
check "SIGTERM: the journal kept" [ -s "$tmp/term.journal/journal" ]

# a journal of other inputs: refused, kept, --fresh named; other overrides the same
FOOTSIM_TEST_SIGNAL_AFTER="1 9" camp -j 2 --out "$tmp/other" >/dev/null 2>&1
cp "$tmp/other.journal/journal" "$tmp/journal.before"
camp -j 2 --out "$tmp/other" --set run.step_s=2e-4 >/dev/null 2>"$tmp/other.err"
check "other overrides: exit 2" [ $? -eq 2 ]
check "other overrides: says what differs and names --fresh" grep -q "settings: 'step_s 0.0002,' in this run, 'step_s 0.0001,' in the journal.*--fresh" "$tmp/other.err"
sed -i "s/^landed_tilt_deg = 15/landed_tilt_deg = 14/" "$tmp/trial.ini"
camp -j 2 --out "$tmp/other" >/dev/null 2>"$tmp/other2.err"
check "another input file content: exit 2" [ $? -eq 2 ]
check "another input file content: names the file" grep -q "inputs: 'trial.ini=[0-9a-f]*' in this run, 'trial.ini=[0-9a-f]*' in the journal" "$tmp/other2.err"
check "refused journals are kept as they were" cmp -s "$tmp/journal.before" "$tmp/other.journal/journal"
sed -i "s/^landed_tilt_deg = 14/landed_tilt_deg = 15/; 1s/^/; a comment changes nothing\n/" "$tmp/trial.ini"
camp -j 2 --out "$tmp/other" >/dev/null 2>&1
check "a comment edit is the same input: the journal resumed, exit 0" [ $? -eq 0 ]
same_as_ref "$tmp/other" "resumed after a comment edit"

# a finished folder of the same campaign: nothing to do, nothing touched
ls -l --time-style=full-iso "$tmp/ref" >"$tmp/ref.before"
camp -j 2 --out "$tmp/ref" >"$tmp/noop.out" 2>"$tmp/noop.err"
check "a finished folder: exit 0" [ $? -eq 0 ]
check "a finished folder: says nothing to do" grep -q 'already holds this campaign.s finished results.*nothing to do' "$tmp/noop.out"
check "a finished folder: ran nothing" [ ! -s "$tmp/noop.err" ]
ls -l --time-style=full-iso "$tmp/ref" >"$tmp/ref.after"
check "a finished folder: untouched" cmp -s "$tmp/ref.before" "$tmp/ref.after"
camp -j 2 --out "$tmp/ref" --set campaign.seeds=2 >/dev/null 2>&1
check "the folder with other seeds: run and replaced" grep -q '"seeds":	2' "$tmp/ref/summary.json"
camp -j 2 --out "$tmp/ref" >/dev/null 2>&1

# --fresh: the journal of another run is removed and the campaign starts over
FOOTSIM_TEST_SIGNAL_AFTER="1 9" camp -j 2 --out "$tmp/fresh" --set run.step_s=2e-4 >/dev/null 2>&1
camp -j 2 --out "$tmp/fresh" --fresh >/dev/null 2>"$tmp/fresh.err"
check "--fresh: exit 0" [ $? -eq 0 ]
check "--fresh: started over" [ -z "$(grep resuming "$tmp/fresh.err")" ]
same_as_ref "$tmp/fresh" "--fresh"
camp -j 2 --out "$tmp/fresh" --fresh >"$tmp/fresh2.out" 2>/dev/null
check "--fresh on a finished folder runs it again" grep -q '^campaign small: 6 trials' "$tmp/fresh2.out"

# a damaged record in the middle of a journal: refused, not guessed at
FOOTSIM_TEST_SIGNAL_AFTER="2 9" camp -j 2 --out "$tmp/bad" >/dev/null 2>&1
sed -i '$s/ 0x/ zz/' "$tmp/bad.journal/journal"
echo '0 1 0 6 1 0x0p+0 |' >>"$tmp/bad.journal/journal"
camp -j 2 --out "$tmp/bad" >/dev/null 2>"$tmp/bad.err"
check "a damaged journal: exit 2" [ $? -eq 2 ]
check "a damaged journal: file:line" grep -q 'bad.journal/journal:[0-9]*: not a trial record' "$tmp/bad.err"

echo "cli_campaign_resume: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
