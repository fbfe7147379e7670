#!/bin/sh
# footsim campaign survives interruption (issue 13 §1): a campaign killed (SIGKILL, at chosen
# points through FOOTSIM_TEST_SIGNAL_AFTER, and again during its resume) or stopped (SIGINT,
# SIGTERM) and then run again finishes with files byte for byte those of an uninterrupted run; a
# stop says how many trials are done and the command that continues, exit 130/143; a journal of
# other inputs is refused (exit 2, naming --fresh) and kept; a comment edit is not another input;
# a torn last record runs again; a finished folder is left alone; --fresh starts over.
# Issue 33: the journal cut at every record boundary and inside each record, by a size limit, by a
# SIGTERM after a cut, or damaged (a digit, an outcome, a nan: caught by the records' checksums,
# named by line, the records before kept) resumes to the uninterrupted run's bytes; a journal of
# format 1 resumes when clean and is refused naming --fresh when not; CR LF, a FIFO and a symbolic
# link are refused (exit 2) with what they are; a finished folder whose expectations failed exits 1
# again.
# Usage: cli_campaign_resume.sh path/to/footsim (run from the source folder).
. "$(dirname "$0")/cli_check.sh"

. tests/small_campaign.sh
# killed_edited NAME N EDIT...: the campaign into $tmp/NAME killed (SIGKILL) once N trials are in
# its journal, the journal edited (EDIT... JOURNAL), then run again (stderr: $tmp/NAME.err); its status
killed_edited() {
    name=$1 after=$2
    shift 2
    FOOTSIM_TEST_SIGNAL_AFTER="$after 9" camp -j 2 --out "$tmp/$name" >/dev/null 2>&1
    "$@" "$tmp/$name.journal/journal"
    camp -j 2 --out "$tmp/$name" >/dev/null 2>"$tmp/$name.err"
}
records() { grep -c '^[0-9]* [0-9a-f]\{8\} [0-9]' "$1"; } # the trial records in journal $1
same_as_ref() { # same_as_ref DIR WHAT
    for f in $files; do
        check_that "$2: $f byte for byte an uninterrupted run's" cmp -s "$tmp/ref/$f" "$1/$f"
    done
    check_that "$2: the journal is removed" [ ! -e "$1.journal" ]
    check_that "$2: no partial folder or lock left" [ -z "$(ls -a "$tmp" | grep -e '\.partial\.' -e 'footsim-lock')" ]
}

camp -j 2 --out "$tmp/ref" >/dev/null 2>&1
check_that "the uninterrupted run exits 0" [ $? -eq 0 ]
check_that "it leaves no journal" [ ! -e "$tmp/ref.journal" ]

# SIGKILL after 1 trial, then resumed on another number of workers
FOOTSIM_TEST_SIGNAL_AFTER="1 9" camp -j 2 --out "$tmp/k1" >/dev/null 2>&1
check_that "SIGKILL: exit 137" [ $? -eq 137 ]
check_that "SIGKILL: the journal holds the trial" [ "$(records "$tmp/k1.journal/journal")" -eq 1 ]
check_that "SIGKILL: no results folder yet" [ ! -e "$tmp/k1" ]
camp -j 1 --out "$tmp/k1" >/dev/null 2>"$tmp/k1.err"
check_that "resumed after SIGKILL: exit 0" [ $? -eq 0 ]
check_that "resumed: said so" grep -q 'resuming from .*k1.journal/journal: 1 of 6 trials done, 5 to run' "$tmp/k1.err"
same_as_ref "$tmp/k1" "resumed after a SIGKILL at 1"

# SIGKILL after 4 trials, SIGKILL again 1 trial into the resume, then resumed
FOOTSIM_TEST_SIGNAL_AFTER="4 9" camp -j 2 --out "$tmp/k4" >/dev/null 2>&1
FOOTSIM_TEST_SIGNAL_AFTER="1 9" camp -j 2 --out "$tmp/k4" >/dev/null 2>&1
check_that "killed twice: the journal holds 5 trials" [ "$(records "$tmp/k4.journal/journal")" -eq 5 ]
camp -j 2 --out "$tmp/k4" >/dev/null 2>&1
check_that "resumed after two kills: exit 0" [ $? -eq 0 ]
same_as_ref "$tmp/k4" "resumed after SIGKILLs at 4 and 5"

# a record cut short by a kill in the middle of its write: ignored, its trial runs again
FOOTSIM_TEST_SIGNAL_AFTER="2 9" camp -j 2 --out "$tmp/torn" >/dev/null 2>&1
printf '352 0badc0de 5 3 0 6 1500 0x1.8p' >>"$tmp/torn.journal/journal"
camp -j 2 --out "$tmp/torn" >/dev/null 2>"$tmp/torn.err"
check_that "a torn last record: exit 0" [ $? -eq 0 ]
check_that "a torn last record: not counted" grep -q '2 of 6 trials done, 4 to run' "$tmp/torn.err"
same_as_ref "$tmp/torn" "resumed after a torn record"

# SIGINT after 2 trials: one line with the count and the command, exit 130; that command finishes
FOOTSIM_TEST_SIGNAL_AFTER="2 2" camp -j 2 --out "$tmp/int" >/dev/null 2>"$tmp/int.err"
check_that "SIGINT: exit 130" [ $? -eq 130 ]
check_that "SIGINT: one line with the trials done and where they are" \
    grep -q "^footsim campaign: stopped by SIGINT: 2 of 6 trials done, kept in $tmp/int.journal/; to continue: footsim campaign " "$tmp/int.err"
check_that "SIGINT: no worker left" [ -z "$(ps -eo args= | grep -F "$tmp/small.ini" | grep -v grep)" ]
check_that "SIGINT: no results folder" [ ! -e "$tmp/int" ]
check_that "SIGINT: no partial folder" [ -z "$(ls "$tmp" | grep '\.partial\.')" ]
again=$(sed -n 's/^footsim campaign: stopped by SIGINT: .*; to continue: footsim //p' "$tmp/int.err")
check_that "SIGINT: the command names the overrides" [ -n "$(echo "$again" | grep -e '--set run.duration_s=0.15')" ]
eval "nice \"\$fs\" $again" >/dev/null 2>"$tmp/int2.err"
check_that "the printed command finishes it: exit 0" [ $? -eq 0 ]
check_that "the printed command resumed" grep -q '2 of 6 trials done, 4 to run' "$tmp/int2.err"
same_as_ref "$tmp/int" "resumed after SIGINT"

# SIGTERM from outside, while the trials run: exit 143, the journal kept
(exec nice "$fs" campaign "$tmp/small.ini" --set run.duration_s=0.15 -j 2 --out "$tmp/term" >/dev/null 2>"$tmp/term.err") &
pid=$!
n=0
until [ "$(records "$tmp/term.journal/journal" 2>/dev/null)" -gt 0 ] 2>/dev/null || [ $n -ge 600 ]; do sleep 0.05; n=$((n + 1)); done
kill -TERM $pid
wait $pid
check_that "SIGTERM: exit 143" [ $? -eq 143 ]
check_that "SIGTERM: said so" grep -q '^footsim campaign: stopped by SIGTERM: [0-9] of 6 trials done' "$tmp/term.err"
check_that "SIGTERM: the journal kept" [ -s "$tmp/term.journal/journal" ]

# a journal of other inputs: refused, kept, --fresh named; other overrides the same
FOOTSIM_TEST_SIGNAL_AFTER="1 9" camp -j 2 --out "$tmp/other" >/dev/null 2>&1
cp "$tmp/other.journal/journal" "$tmp/journal.before"
camp -j 2 --out "$tmp/other" --set run.step_s=2e-4 >/dev/null 2>"$tmp/other.err"
check_that "other overrides: exit 2" [ $? -eq 2 ]
check_that "other overrides: says what differs and names --fresh" grep -q "settings: 'step_s 0.0002,' in this run, 'step_s 0.0001,' in the journal.*--fresh" "$tmp/other.err"
sed -i "s/^landed_tilt_deg = 15/landed_tilt_deg = 14/" "$tmp/trial.ini"
camp -j 2 --out "$tmp/other" >/dev/null 2>"$tmp/other2.err"
check_that "another input file content: exit 2" [ $? -eq 2 ]
check_that "another input file content: names the file" grep -q "inputs: 'trial.ini=[0-9a-f]*' in this run, 'trial.ini=[0-9a-f]*' in the journal" "$tmp/other2.err"
check_that "refused journals are kept as they were" cmp -s "$tmp/journal.before" "$tmp/other.journal/journal"
sed -i "s/^landed_tilt_deg = 14/landed_tilt_deg = 15/; 1s/^/; a comment changes nothing\n/" "$tmp/trial.ini"
camp -j 2 --out "$tmp/other" >/dev/null 2>&1
check_that "a comment edit is the same input: the journal resumed, exit 0" [ $? -eq 0 ]
same_as_ref "$tmp/other" "resumed after a comment edit"

# a finished folder of the same campaign: nothing to do, nothing touched
ls -l --time-style=full-iso "$tmp/ref" >"$tmp/ref.before"
camp -j 2 --out "$tmp/ref" >"$tmp/noop.out" 2>"$tmp/noop.err"
check_that "a finished folder: exit 0" [ $? -eq 0 ]
check_that "a finished folder: says nothing to do" grep -q 'already holds this campaign.s finished results.*nothing to do' "$tmp/noop.out"
check_that "a finished folder: ran nothing" [ ! -s "$tmp/noop.err" ]
ls -l --time-style=full-iso "$tmp/ref" >"$tmp/ref.after"
check_that "a finished folder: untouched" cmp -s "$tmp/ref.before" "$tmp/ref.after"
camp -j 2 --out "$tmp/ref" --set campaign.seeds=2 >/dev/null 2>&1
check_that "the folder with other seeds: run and replaced" grep -q '"seeds":	2' "$tmp/ref/summary.json"
camp -j 2 --out "$tmp/ref" >/dev/null 2>&1

# --fresh: the journal of another run is removed and the campaign starts over
FOOTSIM_TEST_SIGNAL_AFTER="1 9" camp -j 2 --out "$tmp/fresh" --set run.step_s=2e-4 >/dev/null 2>&1
camp -j 2 --out "$tmp/fresh" --fresh >/dev/null 2>"$tmp/fresh.err"
check_that "--fresh: exit 0" [ $? -eq 0 ]
check_that "--fresh: started over" [ -z "$(grep resuming "$tmp/fresh.err")" ]
same_as_ref "$tmp/fresh" "--fresh"
camp -j 2 --out "$tmp/fresh" --fresh >"$tmp/fresh2.out" 2>/dev/null
check_that "--fresh on a finished folder runs it again" grep -q '^campaign small: 6 trials' "$tmp/fresh2.out"

# a damaged record in the middle of a journal (and a line that is no record after it): named by
# line; the record before it kept, it and what follows cut off and run again
mangle() { sed -i '$s/ 0x/ zz/' "$1" && echo '0 1 0 6 1 0x0p+0 |' >>"$1"; }
killed_edited bad 2 mangle
check_that "a damaged journal: resumed, exit 0" [ $? -eq 0 ]
check_that "a damaged journal: file:line, what is wrong, what is kept" grep -q 'bad.journal/journal:9: the record fails its checksum.*; the records before that line are kept, it and every line after it are cut off, and their trials run again' "$tmp/bad.err"
check_that "a damaged journal: the one record before it kept" grep -q '1 of 6 trials done, 5 to run' "$tmp/bad.err"
same_as_ref "$tmp/bad" "resumed after a damaged record"

# ---- issue 33 -------------------------------------------------------------------------------
# A whole journal (every trial recorded, killed before the results were written) cut at every
# record boundary, in the middle of each record and one byte either side of one boundary (the same
# torn-record path as a cut mid-record; test_campaign_journal cuts the library's reader at every
# byte), then resumed: an uninterrupted run's bytes every time.
FOOTSIM_TEST_SIGNAL_AFTER="6 9" camp -j 2 --out "$tmp/all" >/dev/null 2>&1
full="$tmp/all.journal/journal"
check_that "a journal of all 6 trials" [ "$(records "$full")" -eq 6 ]
rm -rf "$tmp"/all.partial.* "$tmp/.all.footsim-lock" # what the kill left beside the folder
head_bytes=$(grep -v '^[0-9]' "$full" | wc -c)
offsets=""
at=$head_bytes
k=0
for len in $(grep '^[0-9]' "$full" | awk '{ print length($0) + 1 }') ""; do
    offsets="$offsets $at"
    [ $k -eq 2 ] && offsets="$offsets $((at - 1)) $((at + 1))"
    [ -n "$len" ] && offsets="$offsets $((at + len / 2))" && at=$((at + len))
    k=$((k + 1))
done
size=$(wc -c <"$full")
bad_cuts=""
n=0
for cut in $offsets; do
    [ "$cut" -ge "$head_bytes" ] && [ "$cut" -le "$size" ] || continue
    n=$((n + 1))
    mkdir "$tmp/cut$n.journal"
    head -c "$cut" "$full" >"$tmp/cut$n.journal/journal"
    camp -j 2 --out "$tmp/cut$n" >/dev/null 2>"$tmp/cut.err" || bad_cuts="$bad_cuts $cut(exit)"
    for f in $files; do cmp -s "$tmp/ref/$f" "$tmp/cut$n/$f" || bad_cuts="$bad_cuts $cut($f)"; done
    [ ! -e "$tmp/cut$n.journal" ] || bad_cuts="$bad_cuts $cut(journal left)"
    rm -rf "$tmp/cut$n"
done
check_that "cut at $n offsets (boundaries, mid-record, +-1 byte) and resumed: an uninterrupted run's bytes each time (wrong at:$bad_cuts)" [ -z "$bad_cuts" ] && [ "$n" -eq 15 ]
mkdir "$tmp/head.journal" && head -c "$((head_bytes - 1))" "$full" >"$tmp/head.journal/journal"
camp -j 2 --out "$tmp/head" >/dev/null 2>"$tmp/head.err"
check_that "a journal cut inside its header: refused (exit 2)" [ $? -eq 2 ]
check_that "a journal cut inside its header: said, naming --fresh" grep -q "header ends early.*--fresh" "$tmp/head.err"

# issue 33 §2: cut 40 bytes short (a full disk), resumed and stopped by SIGTERM after one more
# trial, resumed again: the fragment was cut off before the new record, so the journal reads
FOOTSIM_TEST_SIGNAL_AFTER="3 9" camp -j 2 --out "$tmp/seq" >/dev/null 2>&1
truncate -s -40 "$tmp/seq.journal/journal"
FOOTSIM_TEST_SIGNAL_AFTER="1 15" camp -j 2 --out "$tmp/seq" >/dev/null 2>"$tmp/seq.err"
check_that "cut short, resumed, stopped: exit 143" [ $? -eq 143 ]
check_that "the torn record was said and cut off" grep -q 'ends in a record cut short.*it is cut off and its trial runs again' "$tmp/seq.err"
truncate -s -7 "$tmp/seq.journal/journal"
FOOTSIM_TEST_SIGNAL_AFTER="1 9" camp -j 1 --out "$tmp/seq" >/dev/null 2>&1
camp -j 2 --out "$tmp/seq" >/dev/null 2>"$tmp/seq2.err"
check_that "cut, resumed, stopped, cut, killed, resumed: exit 0" [ $? -eq 0 ]
same_as_ref "$tmp/seq" "resumed after a sequence of cuts and stops"

# issue 33 §12: a flipped digit, another outcome, a nan in a record: caught by its checksum, named
# by line (the header's 8 lines, then records), the record before kept; the results as if never
# damaged (on an unchecked journal, the damaged value would be in them)
damage() { # damage NAME SED-EXPRESSION-ON-LINE-10
    killed_edited "$1" 4 sed -i "10$2"
    check_that "$1: resumed, exit 0" [ $? -eq 0 ]
    check_that "$1: named by line, the 2 records before it kept" grep -q "$1.journal/journal:10: the record .*; the records before that line are kept" "$tmp/$1.err"
    check_that "$1: 2 of 6 done" grep -q '2 of 6 trials done, 4 to run' "$tmp/$1.err"
    same_as_ref "$tmp/$1" "$1"
}
damage digit 's/\( 0x1\.[0-9a-f]*\)\([0-9]\)p/\1\2\2p/'
damage outcome 's/^\([0-9]* [0-9a-f]* [0-9]* [0-9]*\) [0-9] /\1 1 /'
damage nan 's/^\(\([^ ]* \)\{8\}\)[^ ]*/\1nan/'

# a journal of format 1 (an earlier footsim's: no check line, no frames) that reads cleanly:
# resumed (rewritten in format 2); one with a fragment followed by a record (what that footsim's
# append after a cut made): refused, naming --fresh, kept as it was
to_format1() { sed -e '1s/ 2$/ 1/' -e '/^check /d' -e 's/^[0-9]* [0-9a-f]\{8\} //' "$1"; }
as_format1() { to_format1 "$1" >"$tmp/v1.old" && cp "$tmp/v1.old" "$1"; }
killed_edited v1 3 as_format1
check_that "format 1: resumed, exit 0" [ $? -eq 0 ]
check_that "format 1: said so" grep -q "earlier footsim's journal format (1); its 3 records read cleanly" "$tmp/v1.err"
check_that "format 1: 3 of 6 done" grep -q '3 of 6 trials done, 3 to run' "$tmp/v1.err"
same_as_ref "$tmp/v1" "a format-1 journal resumed"
as_torn_format1() { to_format1 "$1" | sed '8s/^\(.\{40\}\).*/\1/' | sed '8{N;s/\n//}' >"$tmp/v1bad.old" && cp "$tmp/v1bad.old" "$1"; }
killed_edited v1bad 3 as_torn_format1
check_that "format 1 with a fragment inside: exit 2" [ $? -eq 2 ]
check_that "format 1 with a fragment inside: file:line, --fresh" grep -q "v1bad.journal/journal:8: not a trial record;.*--fresh" "$tmp/v1bad.err"
check_that "format 1 with a fragment inside: kept as it was" cmp -s "$tmp/v1bad.old" "$tmp/v1bad.journal/journal"

# CR LF line ends (a Windows editor or transfer): named as such, not as a difference of two lines
# that look the same; the journal kept as it was
as_crlf() { sed -i 's/$/\r/' "$1" && cp "$1" "$tmp/crlf.before"; }
killed_edited crlf 1 as_crlf
check_that "CR LF: exit 2" [ $? -eq 2 ]
check_that "CR LF: named, with the way back and --fresh" grep -q "crlf.journal/journal:1: the journal's lines end in CR LF.*--fresh" "$tmp/crlf.err"
check_that "CR LF: kept as it was" cmp -s "$tmp/crlf.before" "$tmp/crlf.journal/journal"

# a FIFO where the journal is (or a shard's trials.journal given to merge): refused with its kind,
# exit 2, never waited on (timeout: a hang fails the check instead of the suite)
mkdir "$tmp/fifo.journal" && mkfifo "$tmp/fifo.journal/journal"
timeout 60 "$fs" campaign "$tmp/small.ini" --set run.duration_s=0.15 --out "$tmp/fifo" >/dev/null 2>"$tmp/fifo.err"
check_that "a FIFO journal: exit 2" [ $? -eq 2 ]
check_that "a FIFO journal: says it is a FIFO" grep -q 'fifo.journal/journal: is a FIFO' "$tmp/fifo.err"
mkdir "$tmp/fifoshard" && mkfifo "$tmp/fifoshard/trials.journal"
timeout 60 "$fs" merge "$tmp/fifoshard" --out "$tmp/fifomerged" >/dev/null 2>"$tmp/fifoshard.err"
check_that "merge of a FIFO trials.journal: exit 2" [ $? -eq 2 ]
check_that "merge of a FIFO trials.journal: says it is a FIFO" grep -q 'fifoshard/trials.journal: is a FIFO' "$tmp/fifoshard.err"
# a folder where the journal is: named as a folder (not "the header ends early"), exit 2
mkdir -p "$tmp/dirj.journal/journal"
camp -j 2 --out "$tmp/dirj" >/dev/null 2>"$tmp/dirj.err"
check_that "a folder journal: exit 2" [ $? -eq 2 ]
check_that "a folder journal: named as a folder" grep -q 'dirj.journal/journal: is a folder' "$tmp/dirj.err"
# a symbolic link where the journal is: refused as such (exit 2), the file it points to untouched
mkdir "$tmp/link.journal" && ln -s "$tmp/journal.before" "$tmp/link.journal/journal"
cp "$tmp/journal.before" "$tmp/target.before"
camp -j 2 --out "$tmp/link" >/dev/null 2>"$tmp/link.err"
check_that "a symbolic link journal: exit 2" [ $? -eq 2 ]
check_that "a symbolic link journal: named as such" grep -q 'link.journal/journal: is a symbolic link' "$tmp/link.err"
check_that "a symbolic link journal: its target untouched" cmp -s "$tmp/target.before" "$tmp/journal.before"

# a file-size limit (ulimit -f, SIGXFSZ ignored by the command) that the journal reaches: exit 4
# with the system's words, the journal not left mid-record, and a resume without the limit
# finishes with an uninterrupted run's bytes
# (the limit: the header and about two and a half records, in sh's 512-byte blocks)
(ulimit -f $(((head_bytes + 900) / 512)); camp -j 1 --out "$tmp/fsz" >/dev/null 2>"$tmp/fsz.err")
check_that "a file-size limit: exit 4" [ $? -eq 4 ]
check_that "a file-size limit: said" grep -q 'cannot write the journal (File too large)' "$tmp/fsz.err"
check_that "a file-size limit: the journal ends with a whole record" [ "$(tail -c 1 "$tmp/fsz.journal/journal" | od -An -c | tr -d ' ')" = '\n' ]
check_that "a file-size limit: no partial folder or lock left" [ -z "$(ls -a "$tmp" | grep -e '^fsz\.partial\.' -e '^\.fsz\.footsim-lock')" ]
camp -j 2 --out "$tmp/fsz" >/dev/null 2>"$tmp/fsz2.err"
check_that "after the limit: exit 0" [ $? -eq 0 ]
check_that "after the limit: resumed" grep -q 'resuming from' "$tmp/fsz2.err"
same_as_ref "$tmp/fsz" "resumed after a file-size limit"

# a finished folder whose expectations failed: run again, nothing runs and it exits 1 as the run
# that wrote it did, naming the expectation
fail_set="--set expect.all.foot=flat --set expect.all.terrain=bumpy --set expect.all.min_success=1"
camp -j 2 --out "$tmp/unmet" $fail_set >/dev/null 2>&1
check_that "an expectation that fails: exit 1" [ $? -eq 1 ]
camp -j 2 --out "$tmp/unmet" $fail_set >"$tmp/unmet.out" 2>"$tmp/unmet.err"
check_that "run again: exit 1 again" [ $? -eq 1 ]
check_that "run again: nothing to do" grep -q 'nothing to do' "$tmp/unmet.out"
check_that "run again: the failed expectation named" grep -q 'FAILED all: flat on bumpy' "$tmp/unmet.out"
check_that "run again: nothing run" [ ! -s "$tmp/unmet.err" ]

finish cli_campaign_resume
