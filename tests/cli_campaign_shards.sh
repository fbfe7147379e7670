#!/bin/sh
# footsim campaign --shard I/N and footsim merge (issue 13 §4): 3 shards (one of them killed and
# resumed) merged give the files of the campaign run on one machine, byte for byte, as do 2
# shards; a merge is refused (exit 2, saying which) for a shard missing, a shard given twice, a
# shard of other overrides, a campaign changed since the shards ran, a folder that is no shard;
# --shard takes only I/N with 1 <= I <= N; --shard 1/1 is a shard too (a one-task Slurm array); a
# merge into one of its own shards is refused; a record injected from another shard or damaged is
# named for what it is (issue 33). Usage: cli_campaign_shards.sh path/to/footsim (run from
# the source folder).
. "$(dirname "$0")/cli_check.sh"

. tests/small_campaign.sh

camp -j 2 --out "$tmp/ref" >/dev/null 2>&1
check_that "the whole campaign exits 0" [ $? -eq 0 ]

# 3 shards, the second killed after its first trial and run again
camp -j 1 --shard 1/3 --out "$tmp/s1" >"$tmp/s1.out" 2>/dev/null
check_that "shard 1/3 exits 0" [ $? -eq 0 ]
check_that "shard 1/3 ran its 2 of 6 trials" grep -q '^campaign small, shard 1/3: 2 of 6 trials' "$tmp/s1.out"
check_that "a shard folder holds its trials (and the marker) only" [ "$(ls -A "$tmp/s1" | tr '\n' ' ')" = ".footsim-results trials.journal " ]
check_that "shard 1/3 holds trials 0 and 3" [ "$(grep -o '^[0-9]* [0-9a-f]\{8\} [0-9]* ' "$tmp/s1/trials.journal" | cut -d' ' -f3 | tr '\n' ' ')" = "0 3 " ]
FOOTSIM_TEST_SIGNAL_AFTER="1 9" camp -j 1 --shard 2/3 --out "$tmp/s2" >/dev/null 2>&1
check_that "shard 2/3 killed: no folder yet" [ ! -e "$tmp/s2" ]
camp -j 1 --shard 2/3 --out "$tmp/s2" >/dev/null 2>"$tmp/s2.err"
check_that "shard 2/3 resumed" grep -q 'resuming from .*s2.journal/journal: 1 of 2 trials done, 1 to run' "$tmp/s2.err"
camp -j 1 --shard 3/3 --out "$tmp/s3" >/dev/null 2>&1
"$fs" merge "$tmp/s3" "$tmp/s1" "$tmp/s2" --out "$tmp/m3" >"$tmp/m3.out" 2>"$tmp/m3.err"
check_that "merge of 3 shards exits 0" [ $? -eq 0 ]
for f in $files; do
    check_that "3 shards merged: $f byte for byte the single run's" cmp -s "$tmp/ref/$f" "$tmp/m3/$f"
done
camp -j 1 --shard 2/3 --out "$tmp/s2" >"$tmp/again.out" 2>&1
check_that "a finished shard again: nothing to do" grep -q 'already holds this campaign.s finished results' "$tmp/again.out"

# any N: 2 shards
camp -j 2 --shard 1/2 --out "$tmp/h1" >/dev/null 2>&1
camp -j 2 --shard 2/2 --out "$tmp/h2" >/dev/null 2>&1
"$fs" merge "$tmp/h1" "$tmp/h2" --out "$tmp/m2" >/dev/null 2>&1
check_that "merge of 2 shards exits 0" [ $? -eq 0 ]
check_that "2 shards merged: summary.json the single run's" cmp -s "$tmp/ref/summary.json" "$tmp/m2/summary.json"
check_that "2 shards merged: trials.csv the single run's" cmp -s "$tmp/ref/trials.csv" "$tmp/m2/trials.csv"

# refusals, each exit 2 and saying which
"$fs" merge "$tmp/s1" "$tmp/s2" --out "$tmp/bad" >/dev/null 2>"$tmp/miss.err"
check_that "a shard missing: exit 2" [ $? -eq 2 ]
check_that "a shard missing: names it and the command" grep -q '2 of 6 trials missing (the first: trial 2, of shard 3/3).*--shard 3/3 .*--set run.duration_s=0.15' "$tmp/miss.err"
"$fs" merge "$tmp/s1" "$tmp/s2" "$tmp/s3" "$tmp/s2" --out "$tmp/bad" >/dev/null 2>"$tmp/twice.err"
check_that "a shard twice: exit 2" [ $? -eq 2 ]
check_that "a shard twice: names the trial and both folders" grep -q "trial 1 (foot bio on terrain bumpy under robot drop_weight, seed 2) is in both $tmp/s2 and $tmp/s2" "$tmp/twice.err"
"$fs" merge "$tmp/s1" "$tmp/h2" --out "$tmp/bad" >/dev/null 2>"$tmp/mixed.err"
check_that "overlapping shards of two splits: exit 2" [ $? -eq 2 ]
camp -j 1 --shard 3/3 --set run.step_s=2e-4 --out "$tmp/s3other" >/dev/null 2>&1
"$fs" merge "$tmp/s1" "$tmp/s2" "$tmp/s3other" --out "$tmp/bad" >/dev/null 2>"$tmp/other.err"
check_that "a shard of other overrides: exit 2" [ $? -eq 2 ]
check_that "a shard of other overrides: says what differs" grep -q "s3other and .*s1 are shards of different campaigns or inputs (settings: 'step_s 0.0002,' in" "$tmp/other.err"
"$fs" merge "$tmp/s1" "$tmp/ref" --out "$tmp/bad" >/dev/null 2>"$tmp/noshard.err"
check_that "a folder that is no shard: exit 2" [ $? -eq 2 ]
check_that "a folder that is no shard: said so" grep -q "ref: holds no trials.journal" "$tmp/noshard.err"
# issue 33 item 9: --out one of merge's inputs (by device and inode, whatever the name) is refused,
# before anything is written: the shard's journal stays
cp "$tmp/s1/trials.journal" "$tmp/s1.journal.before"
"$fs" merge "$tmp/s1" "$tmp/s2" "$tmp/s3" --out "$tmp/s1" >/dev/null 2>"$tmp/self.err"
check_that "merge --out a shard it reads: exit 2" [ $? -eq 2 ]
check_that "merge --out a shard it reads: said so" grep -q "is the shard folder .*s1 given to merge" "$tmp/self.err"
check_that "merge --out a shard it reads: its journal untouched" cmp -s "$tmp/s1.journal.before" "$tmp/s1/trials.journal"
"$fs" merge "$tmp/s1" "$tmp/s2" "$tmp/s3" --out "$tmp//./s3/" >/dev/null 2>"$tmp/self.err"
check_that "merge --out a shard by another name: exit 2" [ $? -eq 2 ]
check_that "merge --out a shard by another name: its journal kept" [ -f "$tmp/s3/trials.journal" ]

# issue 33 item 1: a merge's and a campaign's --out too long to use whole is refused (exit 2, nothing
# written); one that fits, 3500 characters long, works
L=$(long_dir 4080 g)
"$fs" merge "$tmp/s1" "$tmp/s2" "$tmp/s3" --out "$L" >/dev/null 2>"$tmp/long.err"
check_that "merge --out too long: exit 2" [ $? -eq 2 ]
check_that "merge --out too long: says how long and what fits" grep -q "the path is 4080 characters long; footsim takes at most" "$tmp/long.err"
camp -j 2 --out "$L" >/dev/null 2>"$tmp/long.err"
check_that "campaign --out too long: exit 2, nothing written" sh -c "[ $? -eq 2 ] && [ ! -e '$tmp/gggg' ] && [ -z \"\$(ls '$tmp' | grep '^g')\" ]"
F=$(long_dir 3500 f)
"$fs" merge "$tmp/s1" "$tmp/s2" "$tmp/s3" --out "$F" >/dev/null 2>&1
check_that "merge into a 3500-character --out: the single run's summary.json" cmp -s "$tmp/ref/summary.json" "$F/summary.json"
camp -j 2 --out "$F.c" >/dev/null 2>&1
check_that "campaign into a 3500-character --out: the single run's trials.csv" cmp -s "$tmp/ref/trials.csv" "$F.c/trials.csv"

# issue 33 item 11: --shard 1/1 writes a shard (a one-task Slurm array), which merge accepts
camp -j 2 --shard 1/1 --out "$tmp/one" >"$tmp/one.out" 2>&1
check_that "--shard 1/1: exit 0" [ $? -eq 0 ]
check_that "--shard 1/1: a shard folder (its trials.journal only)" [ "$(ls -A "$tmp/one" | tr '\n' ' ')" = ".footsim-results trials.journal " ]
"$fs" merge "$tmp/one" --out "$tmp/m1" >/dev/null 2>"$tmp/m1.err"
check_that "merge of the one shard exits 0" [ $? -eq 0 ]
check_that "the one shard merged: summary.json the single run's" cmp -s "$tmp/ref/summary.json" "$tmp/m1/summary.json"
# the Slurm script as a one-task array runs it (the task's environment as Slurm sets it)
case $fs in /*) ;; *) fs=$PWD/$fs ;; esac
(cd "$tmp" && SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=1 FOOTSIM="$fs" sh "$OLDPWD/tools/slurm/campaign.sbatch" \
    small.ini arr --set run.duration_s=0.15 -j 2 >/dev/null 2>&1 &&
    FOOTSIM="$fs" sh "$OLDPWD/tools/slurm/campaign.sbatch" --merge small.ini arr >/dev/null 2>"$tmp/arr.err")
check_that "a one-task Slurm array, then its merge: exit 0" [ $? -eq 0 ]
check_that "a one-task Slurm array merged: trials.csv the single run's" cmp -s "$tmp/ref/trials.csv" "$tmp/arr/trials.csv"

# issue 33 §14: a record of shard 2 put into shard 1's file (a whole record, its checksum right):
# said for what it is, not as "seed 2, expected 2", and without --fresh, which merge has not
mkdir "$tmp/s1mixed" && cp "$tmp/s1/trials.journal" "$tmp/s1mixed/" && grep '^[0-9]* [0-9a-f]\{8\} 1 ' "$tmp/s2/trials.journal" >>"$tmp/s1mixed/trials.journal"
"$fs" merge "$tmp/s1mixed" "$tmp/s2" "$tmp/s3" --out "$tmp/bad" >/dev/null 2>"$tmp/mixed1.err"
check_that "a record of another shard injected: exit 2" [ $? -eq 2 ]
check_that "a record of another shard injected: said what is wrong" grep -q "s1mixed/trials.journal: holds trial 1, which belongs to shard 2/3, not to shard 1/3 as its header says.*run that shard again" "$tmp/mixed1.err"
check_that "a record of another shard injected: no --fresh (merge has none)" sh -c "! grep -q -e --fresh -e expected '$tmp/mixed1.err'"
# issue 33 §12: a shard's record damaged (a digit changed): refused with file:line (merge never
# changes its inputs), the shard's file kept
mkdir "$tmp/s1bad" && sed '8s/ 0x1\.\([0-9a-f]\)/ 0x1.f\1/' "$tmp/s1/trials.journal" >"$tmp/s1bad/trials.journal"
cp "$tmp/s1bad/trials.journal" "$tmp/s1bad.before"
"$fs" merge "$tmp/s1bad" "$tmp/s2" "$tmp/s3" --out "$tmp/bad" >/dev/null 2>"$tmp/damaged.err"
check_that "a damaged shard record: exit 2" [ $? -eq 2 ]
check_that "a damaged shard record: file:line, what is wrong, run the shard again" grep -q "s1bad/trials.journal:8: the record .*; the file is damaged; run that shard again" "$tmp/damaged.err"
check_that "a damaged shard record: the shard's file untouched" cmp -s "$tmp/s1bad.before" "$tmp/s1bad/trials.journal"
sed -i "s/^landed_tilt_deg = 15/landed_tilt_deg = 14/" "$tmp/trial.ini"
"$fs" merge "$tmp/s1" "$tmp/s2" "$tmp/s3" --out "$tmp/bad" >/dev/null 2>"$tmp/changed.err"
check_that "the campaign changed since: exit 2" [ $? -eq 2 ]
check_that "the campaign changed since: says which input" grep -q "has changed since its shards ran (inputs: 'trial.ini=" "$tmp/changed.err"
check_that "no refused merge wrote anything" [ ! -e "$tmp/bad" ]
for bad in 0/3 4/3 1/0 x 1/2/3 2; do
    camp --shard $bad --out "$tmp/badshard" >/dev/null 2>"$tmp/shard.err"
    check_that "--shard $bad: exit 2" [ $? -eq 2 ]
    check_that "--shard $bad: says what it takes" grep -q 'give I/N' "$tmp/shard.err"
done

finish cli_campaign_shards
