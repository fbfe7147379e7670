#!/bin/sh
# footsim campaign and compare, end to end on a small campaign (2 feet x 1 terrain x 3 seeds):
# -j 1 and -j 4 write identical files (and -j 1 and -j 2 with an error-controlled step); a worker that dies is reported as failed_numerics and the
# campaign goes on; expectations set the exit status; compare exits 0 on identical summaries and
# 1 on a planted change. Usage: cli_campaign.sh path/to/footsim (run from the source folder).
. "$(dirname "$0")/cli_check.sh"

. "$(dirname "$0")/small_campaign.sh"
cat >>"$tmp/small.ini" <<EOF

[expect.anything]
foot = bio
terrain = bumpy
min_success = 0
max_success = 1
EOF

# the same campaign on 1 and on 4 workers: the same files, byte for byte
"$fs" campaign "$tmp/small.ini" -j 1 --out "$tmp/j1" >"$tmp/j1.out" 2>"$tmp/j1.err"
check_that "campaign -j 1 exits 0 (its expectation holds)" [ $? -eq 0 ]
"$fs" campaign "$tmp/small.ini" -j 4 --out "$tmp/j4" >"$tmp/j4.out" 2>"$tmp/j4.err"
check_that "campaign -j 4 exits 0" [ $? -eq 0 ]
for f in $files; do
    check_that "$f written" [ -s "$tmp/j1/$f" ]
    check_that "$f the same with -j 1 and -j 4" cmp -s "$tmp/j1/$f" "$tmp/j4/$f"
done
# with an error-controlled step (run.tolerance_m): the steps each trial takes, rejects and puts back
# are its own, so 1 and 2 workers write the same bytes too
"$fs" campaign "$tmp/small.ini" -j 1 --set run.tolerance_m=1e-5 --out "$tmp/t1" >/dev/null 2>&1
check_that "a variable-step campaign on 1 worker exits 0" [ $? -eq 0 ]
"$fs" campaign "$tmp/small.ini" -j 2 --set run.tolerance_m=1e-5 --out "$tmp/t2" >/dev/null 2>&1
check_that "a variable-step campaign on 2 workers exits 0" [ $? -eq 0 ]
for f in summary.json trials.csv; do
    check_that "variable steps: $f the same with -j 1 and -j 2" cmp -s "$tmp/t1/$f" "$tmp/t2/$f"
done
check_that "variable steps: the settings say the tolerance" grep -q 'tolerance_m 1e-05' "$tmp/t1/summary.json"
check_that "rows in order of foot, terrain, seed" [ "$(cut -d, -f1,2,4 "$tmp/j1/trials.csv" | tr '\n' ' ')" = \
    "foot,terrain,seed bio,bumpy,1 bio,bumpy,2 bio,bumpy,3 flat,bumpy,1 flat,bumpy,2 flat,bumpy,3 " ]
# without a terminal: no bar redrawn with carriage returns, but plain progress lines (at each tenth
# of the trials and at the end); stderr holds nothing else but, gnuplot being optional, the line
# that says the chart was skipped
grep -v 'gnuplot is not installed' "$tmp/j1.err" | grep -v '^footsim campaign: [0-9]*/6 trials done, 0 failed, ' >"$tmp/j1.rest"
check_that "no progress bar when stderr is not a terminal" [ ! -s "$tmp/j1.rest" ]
check_that "no carriage return without a terminal" [ -z "$(tr -dc '\r' <"$tmp/j1.err")" ]
check_that "a plain progress line at the end" grep -q '^footsim campaign: 6/6 trials done, 0 failed, ' "$tmp/j1.err"
check_that "at most a line per tenth and the end" [ "$(grep -c 'trials done' "$tmp/j1.err")" -le 11 ]
check_that "summary.json has the row fields" grep -q '"median_peak_force_N"' "$tmp/j1/summary.json"
check_that "summary.csv names its columns with units" grep -q '^foot,terrain,robot,trials,landed,fell,undecided,failed_numerics,hung,success_rate,ci_low,ci_high,median_end_time_s,' "$tmp/j1/summary.csv"
check_that "trials.csv names the rule that decided each trial" grep -q "^foot,terrain,robot,seed,x_m,y_m,yaw_deg,pitch_deg,roll_deg,outcome,rule," "$tmp/j1/trials.csv"

# a worker that dies on seed 2 (as an ODE error makes it, exit 3): failed_numerics, the campaign
# goes on; an expectation that cannot hold then fails with exit 1, after the results are written;
# without gnuplot on the PATH the chart is skipped with a message
mkdir "$tmp/nopath"
FOOTSIM_TEST_CRASH_SEED=2 PATH="$tmp/nopath" "$fs" campaign "$tmp/small.ini" -j 2 --out "$tmp/crash" \
    --set expect.all.foot=flat --set expect.all.terrain=bumpy --set expect.all.min_success=1 \
    >"$tmp/crash.out" 2>"$tmp/crash.err"
check_that "a failed expectation exits 1" [ $? -eq 1 ]
check_that "the failed expectation is named with its numbers" grep -q 'FAILED all: flat on bumpy under drop_weight landed . of 3' "$tmp/crash.out"
check_that "the dead worker's trials are failed_numerics" [ "$(grep -c ',2,.*failed_numerics,.*seed 2, exited with status 3' "$tmp/crash/trials.csv")" -eq 2 ]
check_that "the other trials ran" [ "$(tail -n +2 "$tmp/crash/trials.csv" | grep -c -v failed_numerics)" -eq 4 ]
check_that "the summary counts them" grep -q '"failed_numerics":	1' "$tmp/crash/summary.json"
check_that "the death is reported on stderr" grep -q 'foot bio on terrain bumpy under robot drop_weight, seed 2, exited with status 3' "$tmp/crash.err"
check_that "no gnuplot: said so" grep -q 'gnuplot is not installed' "$tmp/crash.err"
check_that "no gnuplot: no chart" [ ! -e "$tmp/crash/success.png" ]

# provenance: every result file says what made it; compare refuses other overrides unless --force
check_that "trials.csv starts with its header, its provenance in summary.json" sh -c "head -1 '$tmp/j1/trials.csv' | grep -q '^foot,terrain,robot,seed,' &&
    tr -d ' \t\n' <'$tmp/j1/summary.json' | grep -q '\"seeds\":3,\"first_seed\":1' && grep -q '\"path\":[[:space:]]*\"small.ini\"' '$tmp/j1/summary.json'"
check_that "summary.json records the version and the inputs' hashes" grep -q '"hash":' "$tmp/j1/summary.json"
"$fs" campaign "$tmp/small.ini" -j 2 --out "$tmp/other" --set run.step_s=2e-4 >/dev/null 2>&1
"$fs" compare "$tmp/other/summary.json" "$tmp/j1/summary.json" >"$tmp/prov.out" 2>"$tmp/prov.err"
check_that "compare refuses results of other overrides (exit 6: inputs differ)" [ $? -eq 6 ]
check_that "and names the difference" grep -q 'provenance: overrides differs' "$tmp/prov.out"
"$fs" compare "$tmp/other/summary.json" "$tmp/j1/summary.json" --force >"$tmp/prov.out" 2>&1
check_that "compare --force compares them anyway (exit 0 or 1)" [ $? -le 1 ]

# a run's metrics.json and a trial's trial.json record what made them the same way
"$fs" run scenarios/static_load.ini --set run.duration_s=0.02 --out "$tmp/run" >/dev/null 2>&1
check_that "metrics.json records the version, the overrides and the inputs' hashes" sh -c "tr -d ' \t\n' <'$tmp/run/metrics.json' |
    grep -q '\"provenance\":{\"footsim\":\"[^\"]*\",\"overrides\":\[\"run.duration_s=0.02\"\],\"inputs\":\[{\"path\":\"static_load.ini\",\"hash\":\"[0-9a-f]\{16\}\"}'"
check_that "and the settings" grep -q '"settings":.*"step_s 0.0001, stepper step' "$tmp/run/metrics.json"
"$fs" trial scenarios/campaign_test_trial.ini --seed 2 --set run.duration_s=0.05 --out "$tmp/trial" >/dev/null 2>&1
check_that "trial.json records its seed and its inputs" sh -c "grep -q '\"first_seed\":[[:space:]]*2' '$tmp/trial/trial.json' &&
    grep -q '\"path\":[[:space:]]*\"robots/drop_weight.ini\"' '$tmp/trial/trial.json'"

# optimize: its progress counts evaluations and their trials, as plain lines in a log
opt_ini
"$fs" optimize "$tmp/opt.ini" -j 2 --set run.duration_s=0.3 --set campaign.seeds=1 --out "$tmp/opt" >/dev/null 2>"$tmp/opt.err"
check_that "a tiny optimize runs (exit 0: its target holds)" [ $? -eq 0 ]
check_that "optimize: no carriage return in a log" [ -z "$(tr -dc '\r' <"$tmp/opt.err")" ]
check_that "optimize: evaluations.provenance.json says what made evaluations.csv (the optimize file, the campaign's files, every --set)" sh -c \
    "head -1 '$tmp/opt/evaluations.csv' | grep -q '^evaluation,' && tr -d ' \t\n' <'$tmp/opt/evaluations.provenance.json' |
     grep -q '\"file\":\"evaluations.csv\",\"provenance\":{\"footsim\":\"[^\"]*\",\"overrides\":\[\"run.duration_s=0.3\",\"campaign.seeds=1\"\],\"inputs\":\[{\"path\":\"opt.ini\",\"hash\":\"[0-9a-f]\{16\}\"},{\"path\":\"small.ini\"'"
# the search's one evaluation, then the reruns: the foot's own design, the start and the best on the
# search's seeds, the best on fresh ones
check_that "optimize: evaluations done of at most, then trials" grep -q '^footsim optimize: evaluation 5/5, 2/2 trials done, 0 failed, ' "$tmp/opt.err"
# a sweep of a constraint's bound: one search per value, each in its folder, and the front of their
# bests; 0.2 kg is below Table I's foot (0.277 kg: every candidate breaks it), 0.3 kg above it
printf '[constraint.light]\nof = foot_mass_kg\n' >>"$tmp/opt.ini"
"$fs" optimize "$tmp/opt.ini" -j 2 --set run.duration_s=0.05 --set campaign.seeds=1 --set optimize.sweep=light.max \
    --set optimize.sweep_values=0.2,0.3 --out "$tmp/sweep" >"$tmp/sweep.out" 2>&1
check_that "a sweep of two bounds runs (exit 0: one bound's best meets its target)" [ $? -eq 0 ]
check_that "a sweep: each search's files in its folder" sh -c "[ -s '$tmp/sweep/light_max_0.2/result.md' ] &&
    [ -s '$tmp/sweep/light_max_0.3/evaluations.csv' ] && [ -s '$tmp/sweep/front.provenance.json' ]"
check_that "a sweep: front.csv has the file's design and each bound's best, only the feasible one on the front" sh -c \
    "sed -n 2p '$tmp/sweep/front.csv' | grep -q '^file,,12000,' && sed -n 3p '$tmp/sweep/front.csv' | grep -q '^best,0.2.*,0\$' &&
     sed -n 4p '$tmp/sweep/front.csv' | grep -q '^best,0.2999.*,1\$'"
check_that "a sweep: result.md says which best breaks its bound" grep -q '| best | 0.2 | .*breaks a constraint |' "$tmp/sweep/result.md"
"$fs" optimize "$tmp/opt.ini" --set optimize.sweep=light.max --set optimize.sweep_values=0.3,0.3 --out "$tmp/sweep2" >/dev/null 2>"$tmp/sweep2.err"
check_that "a sweep: a value given twice refused before anything runs (exit 2)" sh -c "[ $? -eq 2 ] && grep -q 'given twice' '$tmp/sweep2.err' && [ ! -e '$tmp/sweep2' ]"

# compare: identical summaries exit 0; a planted change in a rate or a median exits 1
"$fs" compare "$tmp/j4/summary.json" "$tmp/j1/summary.json" >"$tmp/cmp.out"
check_that "compare of identical summaries exits 0" [ $? -eq 0 ]
check_that "compare says identical" grep -q 'identical' "$tmp/cmp.out"
sed '0,/"success_rate":/s/"success_rate":[^,]*/"success_rate":	-1/' "$tmp/j1/summary.json" >"$tmp/rate.json"
"$fs" compare "$tmp/rate.json" "$tmp/j1/summary.json" >"$tmp/cmp.out"
check_that "compare exits 1 when a rate leaves the baseline interval" [ $? -eq 1 ]
check_that "compare names the rate" grep -q '| bio | bumpy | drop_weight | success_rate | .* | -1 |.*outside' "$tmp/cmp.out"
sed '0,/"median_peak_force_N":/s/"median_peak_force_N":[^,]*/"median_peak_force_N":	1e12/' "$tmp/j1/summary.json" >"$tmp/force.json"
"$fs" compare "$tmp/force.json" "$tmp/j1/summary.json" >"$tmp/cmp.out"
check_that "compare exits 1 when a median moves too far" [ $? -eq 1 ]
check_that "compare names the median" grep -q 'median_peak_force_N .* 1e+12 .*outside' "$tmp/cmp.out"
"$fs" compare "$tmp/j1/summary.json" "$tmp/missing.json" 2>"$tmp/cmp.err"
check_that "compare of a missing file exits 2" [ $? -eq 2 ]

# issue 32: compare for CI. A step count is reported, never judged: a change of step alone is no failure
py=/usr/bin/python3
edit() { # edit IN OUT PYTHON-STATEMENT: the summary IN as j, changed, written to OUT
    "$py" -c "import json, sys; j = json.load(open(sys.argv[1])); $3; json.dump(j, open(sys.argv[2], 'w'))" "$1" "$2"
}
edit "$tmp/j1/summary.json" "$tmp/steps.json" 'j["rows"][0]["median_steps"] = 1e12'
"$fs" compare "$tmp/steps.json" "$tmp/j1/summary.json" >"$tmp/cmp.out"
check_that "a step count moved a millionfold: exit 0 (reported, not judged)" [ $? -eq 0 ]
check_that "and the Markdown lists nothing outside" grep -q '^Nothing outside what the baseline allows' "$tmp/cmp.out"
"$fs" compare "$tmp/steps.json" "$tmp/j1/summary.json" --all >"$tmp/cmp.out"
check_that "--all lists it, reported" grep -q '| bio | bumpy | drop_weight | median_steps | .* | 1e+12 | | reported, not judged |' "$tmp/cmp.out"
# a missing median: – in the Markdown (never nan), null in the JSON
edit "$tmp/j1/summary.json" "$tmp/none.json" 'j["rows"][0]["median_settle_time_s"] = None'
"$fs" compare "$tmp/none.json" "$tmp/none.json" --all >"$tmp/cmp.out"
check_that "a missing median is – in the Markdown" grep -q '| bio | bumpy | drop_weight | median_settle_time_s | – | – | \[–, –\] | identical |' "$tmp/cmp.out"
check_that "never nan" sh -c "! grep -qiw nan '$tmp/cmp.out'"
# a median moved within its tolerance: not listed unless --all; the JSON has every quantity
edit "$tmp/j1/summary.json" "$tmp/near.json" 'j["rows"][0]["median_end_time_s"] *= 1.01'
"$fs" compare "$tmp/near.json" "$tmp/j1/summary.json" >"$tmp/cmp.out"
check_that "a median within tolerance: exit 0" [ $? -eq 0 ]
check_that "not listed by default" sh -c "! grep -q median_end_time_s '$tmp/cmp.out' && grep -q 'not listed: --all' '$tmp/cmp.out'"
"$fs" compare "$tmp/near.json" "$tmp/j1/summary.json" --all >"$tmp/cmp.out"
check_that "listed as within by --all" grep -q '| bio | bumpy | drop_weight | median_end_time_s | .* | within |' "$tmp/cmp.out"
check_that "--all lists every quantity: 21 a cell (the rate, the undecided and hung counts, 18 medians)" [ "$(grep -c '^| bio | bumpy | drop_weight | ' "$tmp/cmp.out")" -eq 21 ]
"$fs" compare "$tmp/force.json" "$tmp/j1/summary.json" --json >"$tmp/cmp.json"
check_that "--json exits as the Markdown does (1)" [ $? -eq 1 ]
check_that "--json: one JSON object, every quantity with its verdict, the counts and the exit status" "$py" -c '
import json, sys
j = json.load(open(sys.argv[1]))
q = {(x["foot"], x["robot"], x["quantity"]): x for x in j["quantities"]}
f = q[("bio", "drop_weight", "median_peak_force_N")]
steps = q[("bio", "drop_weight", "median_steps")]
assert j["verdict"] == "changed" and j["exit_status"] == 1 and j["counts"]["outside"] == 1, j["counts"]
assert f["verdict"] == "outside" and f["result"] == 1e12 and f["low"] <= f["baseline"] <= f["high"], f
assert steps["verdict"] == "reported" and len(j["quantities"]) == 2 * 21 == j["counts"]["quantities"]
' "$tmp/cmp.json"
# inputs differ (exit 6), a changed input named by its path, in Markdown and JSON; --force compares
edit "$tmp/j1/summary.json" "$tmp/input.json" '[i.update(hash="0123456789abcdef") for i in j["provenance"]["inputs"] if i["path"] == "trial.ini"]'
"$fs" compare "$tmp/input.json" "$tmp/j1/summary.json" >"$tmp/cmp.out" 2>"$tmp/cmp.err"
check_that "an input changed: exit 6" [ $? -eq 6 ]
check_that "named by its path" grep -q '^provenance: input trial.ini differs: result 0123456789abcdef, baseline [0-9a-f]\{16\}$' "$tmp/cmp.out"
check_that "and only it" [ "$(grep -c '^provenance: ' "$tmp/cmp.out")" -eq 1 ]
"$fs" compare "$tmp/input.json" "$tmp/j1/summary.json" --json >"$tmp/cmp.json" 2>/dev/null
check_that "--json of it: exit 6" [ $? -eq 6 ]
check_that "--json names the input and says why it stopped" "$py" -c '
import json, sys
j = json.load(open(sys.argv[1]))
d = j["provenance"]["differences"]
assert j["verdict"] == "inputs differ" and j["exit_status"] == 6 and j["refused_for"] == "inputs", j
assert d == [{"field": "inputs", "path": "trial.ini", "result": "0123456789abcdef", "baseline": d[0]["baseline"]}], d
assert j["quantities"] == [] and "--force" in j["error"]
' "$tmp/cmp.json"
"$fs" compare "$tmp/input.json" "$tmp/j1/summary.json" --force >/dev/null
check_that "--force compares them: exit 0" [ $? -eq 0 ]
"$fs" compare "$tmp/j1/summary.json" "$tmp/missing.json" --json >"$tmp/cmp.json" 2>/dev/null
status=$?
check_that "cannot read: exit 2, and the JSON says so" sh -c "[ $status -eq 2 ] && grep -q '\"verdict\":[[:space:]]*\"cannot read\"' '$tmp/cmp.json'"
# results written before issue 32 (the CI baseline): still read
"$fs" compare results/baseline/landing.json results/baseline/landing.json --json >"$tmp/cmp.json"
status=$?
check_that "the committed baseline compares with itself: exit 0, identical" sh -c "[ $status -eq 0 ] && grep -q '\"verdict\":[[:space:]]*\"identical\"' '$tmp/cmp.json'"

finish
