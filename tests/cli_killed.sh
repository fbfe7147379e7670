#!/bin/sh
# Issue 16, findings 3 and 9: a campaign killed while writing leaves its old folder whole (no mixed
# folder, no temporary file in it); a render-compare that fails numerically leaves the old frames
# and filmstrip; an ODE error leaves no folder and no partial folder; a stopped worker is killed by
# the watchdog, counted and named; a worker killed from outside is counted killed and runs once more
# (issue 33). Usage: cli_killed.sh path/to/footsim [render|norender].
. "$(dirname "$0")/cli_check.sh"
renderer=${2:-render}
src=$PWD
printf '[campaign]\ntrial = %s/scenarios/campaign_test_trial.ini\nseeds = 2\n[foot.bio]\nfile = %s/scenarios/feet/biomimetic.ini\n[terrain.flat]\nfile = %s/terrains/flat.ini\n' \
    "$src" "$src" "$src" >"$tmp/camp.ini"
short="--set run.duration_s=0.05"
# finding 3: a campaign killed in its write phase
"$fs" campaign "$tmp/camp.ini" $short -j 1 --out "$tmp/c" >/dev/null 2>&1
cp "$tmp/c/summary.json" "$tmp/summary_before.json" && cp "$tmp/c/trials.csv" "$tmp/trials_before.csv"
FOOTSIM_TEST_KILL_IN_WRITE=1 "$fs" campaign "$tmp/camp.ini" $short --set campaign.seeds=3 -j 1 --out "$tmp/c" >/dev/null 2>&1
status=$?
check '[ "$status" -eq 137 ] || [ "$status" -gt 128 ]'
check 'cmp -s "$tmp/summary_before.json" "$tmp/c/summary.json" && cmp -s "$tmp/trials_before.csv" "$tmp/c/trials.csv"'
check '[ -z "$(ls -a "$tmp/c" | grep "\.tmp\.")" ]'
# the next campaign clears what the killed one left beside the folder, and replaces it whole
"$fs" campaign "$tmp/camp.ini" $short --set campaign.seeds=3 -j 1 --out "$tmp/c" >/dev/null 2>&1
check '[ -z "$(ls -a "$tmp" | grep -e "^c\.partial" -e "^\.c\.footsim-lock")" ]'
check '[ "$(grep -c "^bio,flat," "$tmp/c/trials.csv")" -eq 3 ] && grep -q "\"trials\":[[:space:]]*3" "$tmp/c/summary.json"'
# a campaign ended by SIGTERM (or Ctrl-C) in the middle of its trials removes its partial folder
"$fs" campaign "$tmp/camp.ini" $short --set campaign.seeds=400 -j 1 --out "$tmp/c" >/dev/null 2>&1 &
pid=$!
for i in $(seq 100); do [ -n "$(ls -a "$tmp" | grep "^c\.partial")" ] && break; sleep 0.2; done
check '[ -n "$(ls -a "$tmp" | grep "^c\.partial")" ]' # it is running, its partial folder there
kill -TERM $pid
wait $pid
status=$?
check '[ "$status" -eq 143 ] && [ -z "$(ls -a "$tmp" | grep -e "^c\.partial" -e "^\.c\.footsim-lock")" ]'
check '[ "$(grep -c "^bio,flat," "$tmp/c/trials.csv")" -eq 3 ]'
# finding 9: an ODE internal error (exit 3 from ODE's handler) leaves no folder and no partial one
FOOTSIM_TEST_ODE_ERROR=1 "$fs" run scenarios/static_load.ini $short --out "$tmp/ode" >/dev/null 2>&1
status=$?
check '[ "$status" -eq 3 ] && [ ! -e "$tmp/ode" ] && [ -z "$(ls -a "$tmp" | grep -e "^ode\.")" ]'
# finding 9: a worker stopped (SIGSTOP) in a trial is killed by the watchdog, counted and named;
# the campaign finishes instead of waiting forever (5 s: far beyond a 0.05 s trial, even under ASan)
FOOTSIM_TEST_STOP_SEED=2 FOOTSIM_WATCHDOG_S=5 "$fs" campaign "$tmp/camp.ini" $short -j 2 --out "$tmp/w" >/dev/null 2>"$tmp/werr"
status=$?
check '[ "$status" -eq 0 ] && grep -q "seed 2, made no progress for 5 s and was killed by the watchdog" "$tmp/werr"'
# counted as hung, its own outcome, never as a numerical failure (trials.csv, summary.csv, .json)
check 'grep -q "1 worker made no progress.*counted as hung, not as numerical failures" "$tmp/werr" && grep -q "seed 2, .*; counted as hung" "$tmp/werr"'
check '[ "$(grep -c ",hung,watchdog," "$tmp/w/trials.csv")" -eq 1 ] && ! grep -q "failed_numerics,numerics" "$tmp/w/trials.csv"'
check 'grep ",hung,watchdog," "$tmp/w/trials.csv" | grep -q "^bio,flat,drop_weight,2,"'
check 'grep -q "\"hung\":	1" "$tmp/w/summary.json" && grep -q "\"failed_numerics\":	0" "$tmp/w/summary.json"'
check 'grep -q "^foot,terrain,robot,trials,landed,fell,undecided,failed_numerics,hung," "$tmp/w/summary.csv" && grep -q "^bio,flat,drop_weight,[0-9]*,[0-9]*,[0-9]*,[0-9]*,0,1," "$tmp/w/summary.csv"'
# a hung trial goes through the journal as hung: shard 2/2 (seed 2) keeps it in its trials.journal,
# and the merge of both shards counts it hung, never failed_numerics
FOOTSIM_TEST_STOP_SEED=2 FOOTSIM_WATCHDOG_S=5 "$fs" campaign "$tmp/camp.ini" $short -j 2 --shard 2/2 --out "$tmp/s2" >/dev/null 2>&1
"$fs" campaign "$tmp/camp.ini" $short -j 1 --shard 1/2 --out "$tmp/s1" >/dev/null 2>&1
"$fs" merge "$tmp/s1" "$tmp/s2" --out "$tmp/m" >/dev/null 2>&1
status=$?
check '[ "$status" -eq 0 ] && grep ",hung,watchdog," "$tmp/m/trials.csv" | grep -q "^bio,flat,drop_weight,2,"'
check 'grep -q "\"hung\":	1" "$tmp/m/summary.json" && grep -q "\"failed_numerics\":	0" "$tmp/m/summary.json"'
# issue 33 §16: a worker killed from outside (SIGKILL, as the OOM killer kills) is its own outcome,
# killed (rule worker_died), never failed_numerics; its trial runs once more after the others, and
# a second kill is final (the summary files count it with the hung: workers lost, not physics)
FOOTSIM_TEST_KILL_SEED=2 "$fs" campaign "$tmp/camp.ini" $short -j 2 --out "$tmp/kl" >"$tmp/klout" 2>"$tmp/klerr"
status=$?
check '[ "$status" -eq 0 ] && grep -q "seed 2, was killed by signal 9 (Killed); counted as killed for now: it runs once more" "$tmp/klerr"'
check 'grep -q "1 trial whose worker was killed runs once more" "$tmp/klerr" && grep -q "seed 2, was killed by signal 9 (Killed); counted as killed (its second try)" "$tmp/klerr"'
check '[ "$(grep -c ",killed,worker_died," "$tmp/kl/trials.csv")" -eq 1 ] && grep ",killed,worker_died," "$tmp/kl/trials.csv" | grep -q "^bio,flat,drop_weight,2,.*was killed by signal 9"'
check '! grep -q "failed_numerics,numerics" "$tmp/kl/trials.csv" && grep -q "\"failed_numerics\":	0" "$tmp/kl/summary.json" && grep -q "\"hung\":	1" "$tmp/kl/summary.json"'
check 'grep -q "killed 1" "$tmp/klout" && grep -q "or killed from outside: trials.csv says which" "$tmp/kl/summary.md"'
# retried once on resume: the run stopped (kill -9) after the kill was journaled, before its retry;
# resumed without the kill, the trial runs and the files are an unkilled run's, byte for byte
"$fs" campaign "$tmp/camp.ini" $short -j 2 --out "$tmp/klref" >/dev/null 2>&1
FOOTSIM_TEST_KILL_SEED=2 FOOTSIM_TEST_SIGNAL_AFTER="2 9" "$fs" campaign "$tmp/camp.ini" $short -j 2 --out "$tmp/klr" >/dev/null 2>&1
check '[ ! -e "$tmp/klr" ] && [ "$(grep -c " 1 2 5 10 " "$tmp/klr.journal/journal")" -eq 1 ]' # trial 1, seed 2: killed, worker_died
"$fs" campaign "$tmp/camp.ini" $short -j 2 --out "$tmp/klr" >/dev/null 2>"$tmp/klrerr"
status=$?
check '[ "$status" -eq 0 ] && grep -q "resuming from .*: 1 of 2 trials done, 1 to run" "$tmp/klrerr"'
check 'cmp -s "$tmp/klref/trials.csv" "$tmp/klr/trials.csv" && cmp -s "$tmp/klref/summary.json" "$tmp/klr/summary.json" && cmp -s "$tmp/klref/summary.md" "$tmp/klr/summary.md"'
# finding 9: a refused fork (at most one process for an unprivileged user) leaves no folder
if [ "$(id -u)" -eq 0 ] && command -v setpriv >/dev/null && command -v prlimit >/dev/null; then
    mkdir "$tmp/nobody" && chmod 777 "$tmp/nobody" && chmod 755 "$tmp" && cp "$tmp/camp.ini" "$tmp/nobody/" && chmod 644 "$tmp/nobody/camp.ini"
    # (ASAN_OPTIONS: the leak checker needs a thread of its own at exit, which the limit refuses)
    ASAN_OPTIONS=detect_leaks=0 setpriv --reuid=65534 --regid=65534 --clear-groups prlimit --nproc=1 -- \
        "$fs" campaign "$tmp/nobody/camp.ini" $short -j 1 --out "$tmp/nobody/c" >/dev/null 2>"$tmp/ferr"
    status=$?
    check '[ "$status" -eq 4 ] && grep -q "cannot start a worker process (Resource temporarily unavailable)" "$tmp/ferr"'
    check '[ -z "$(ls -a "$tmp/nobody" | grep -e "^c$" -e "^c\\.")" ]'
else
    echo "skipped: needs root, setpriv and prlimit to make fork fail (the refused-fork case of finding 9)"
fi
# finding 3: render-compare failing numerically leaves the old frames and filmstrip
if [ "$renderer" = render ]; then
    rc="render-compare scenarios/static_load.ini scenarios/static_load.ini --size 64x32 --fps 50"
    "$fs" $rc $short --out "$tmp/rc" >/dev/null 2>&1
    n_before=$(ls "$tmp/rc/frames" | wc -l)
    "$fs" $rc --set run.springs=explicit --set run.step_s=1e-3 --set run.duration_s=0.3 --out "$tmp/rc" >/dev/null 2>&1
    status=$?
    check '[ "$status" -eq 3 ] && [ -f "$tmp/rc/filmstrip.png" ] && [ "$(ls "$tmp/rc/frames" | wc -l)" -eq "$n_before" ] && [ "$n_before" -gt 0 ]'
    check '[ -z "$(ls -a "$tmp" | grep -e "^rc\.")" ]'
fi
finish
