#!/bin/sh
# Issue 32: every CSV file footsim writes is read right by a user's tools: one header row first, no
# '#' line, every row as wide as the header, a missing value an empty field, its provenance in the
# JSON beside it. READER csv (Python's csv module) and sqlite (the sqlite3 command's .import, and a
# campaign's schema.sql: typed columns, NULL for a missing value, the provenance) or pandas
# (pandas.read_csv with its defaults; exit 77, skipped, without python3-pandas). Reads the files a
# small campaign, a run, a trial and a design search write, and the committed results.
# Usage: cli_csv.sh path/to/footsim csv|pandas (run from the source folder; Debian's /usr/bin/python3).
. "$(dirname "$0")/cli_check.sh"
reader=$2
py=/usr/bin/python3
checker="$(dirname "$0")/csv_check.py"
if [ "$reader" = pandas ] && ! "$py" -c 'import pandas' 2>/dev/null; then
    echo "pandas is not installed (Debian: apt-get install python3-pandas): skipped"
    exit 77
fi
readers=$reader
[ "$reader" = csv ] && readers="csv sqlite"

. "$(dirname "$0")/small_campaign.sh"
printf '\n[expect.anything]\nfoot = bio\nterrain = bumpy\nmin_success = 0\nmax_success = 1\n' >>"$tmp/small.ini"
camp -j 2 --out "$tmp/c" >/dev/null 2>&1
check_that "a small campaign runs" [ -s "$tmp/c/summary.json" ]
"$fs" run scenarios/static_load.ini --set run.duration_s=0.02 --out "$tmp/run" >/dev/null 2>&1
"$fs" trial scenarios/campaign_test_trial.ini --seed 2 --set run.duration_s=0.05 --out "$tmp/trial" >/dev/null 2>&1
opt_ini
"$fs" optimize "$tmp/opt.ini" -j 2 --set run.duration_s=0.3 --set campaign.seeds=1 --out "$tmp/opt" >/dev/null 2>&1

# what these commands wrote, each with a column that must hold numbers
written="$tmp/c/trials.csv:seed:steps:end_time_s $tmp/c/summary.csv:trials:median_steps
$tmp/run/trajectory.csv $tmp/trial/trajectory.csv $tmp/opt/evaluations.csv:objective"
# the committed results footsim wrote in this format (results/landing_reference, results/bench's
# timings and results/equivalence* are older: see issue 32's report; render.csv is tools/bench-render.sh's)
committed="results/landing/trials.csv:rest_ankle_drop_m:steps results/landing/summary.csv:median_steps
results/roughness/trials.csv:steps results/roughness/summary.csv results/envelope/trials.csv:steps
results/envelope/summary.csv results/envelope_best/trials.csv:steps results/envelope_best/summary.csv
results/envelope_best_drop/trials.csv:steps results/envelope_best_drop/summary.csv
results/bench/render.csv:fps results/bench/own_code_before_after.csv:wall_s"
for r in $readers; do
    # shellcheck disable=SC2086
    "$py" "$checker" "$r" $written $committed >"$tmp/check.out" 2>&1
    status=$?
    check_that "every CSV file read right by $r" [ $status -eq 0 ]
    [ $status -eq 0 ] || grep -v '^ok: ' "$tmp/check.out" >&2
done
for f in trials summary; do
    check_that "$f.csv has no provenance line: summary.json has it" [ "$(head -c 1 "$tmp/c/$f.csv")" != "#" ]
done
check_that "evaluations.csv's provenance beside it" grep -q '"file":[[:space:]]*"evaluations.csv"' "$tmp/opt/evaluations.provenance.json"
check_that "with the overrides of the search" grep -q '"campaign.seeds=1"' "$tmp/opt/evaluations.provenance.json"

if [ "$reader" = csv ]; then
    # the campaign's schema.sql: sqlite3 makes typed tables; an empty field is NULL, never 0 or text
    (cd "$tmp/c" && sqlite3 c.sqlite <schema.sql) 2>"$tmp/sql.err"
    check_that "schema.sql runs in sqlite3 without a message" [ $? -eq 0 ] && [ ! -s "$tmp/sql.err" ]
    q() { sqlite3 "$tmp/c/c.sqlite" "$1"; }
    # the same figures computed by Python from the CSV file, empty fields left out
    want=$("$py" -c '
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1], newline="")))
drops = [float(r["rest_ankle_drop_m"]) for r in rows if r["rest_ankle_drop_m"] != ""]
print("%d %.12g %d %d" % (len(drops), sum(drops) / len(drops) if drops else -1, max(int(r["steps"]) for r in rows), len(rows)))' "$tmp/c/trials.csv")
    got=$(q "SELECT count(rest_ankle_drop_m), printf('%.12g', coalesce(avg(rest_ankle_drop_m), -1)), max(steps), count(*) FROM trials" | tr '|' ' ')
    check_that "sqlite3's count and avg(rest_ankle_drop_m), max(steps) are the file's ($want; got $got)" [ "$got" = "$want" ]
    check_that "steps is an integer column, max(steps) a number" [ "$(q 'SELECT typeof(max(steps)) FROM trials')" = integer ]
    check_that "a missing value is NULL" [ "$(q "SELECT count(*) FROM trials WHERE rest_ankle_drop_m = '' OR failure = ''")" = 0 ]
    check_that "no numeric column holds text" [ "$(q "SELECT count(*) FROM trials WHERE typeof(end_time_s) <> 'real' OR typeof(seed) <> 'integer'")" = 0 ]
    check_that "the summary's medians are numbers" [ "$(q "SELECT typeof(median_steps) FROM summary LIMIT 1")" = real ]
    check_that "every trial a row" [ "$(q 'SELECT sum(trials) FROM summary')" = "$(q 'SELECT count(*) FROM trials')" ]
    version=$("$py" -c 'import json, sys; print(json.load(open(sys.argv[1]))["provenance"]["footsim"])' "$tmp/c/summary.json")
    check_that "the provenance table is summary.json's" [ "$(q 'SELECT footsim FROM provenance')" = "$version" ]
    check_that "with every input and its hash" [ "$(q "SELECT count(*) FROM provenance_inputs WHERE length(hash) = 16")" = \
        "$("$py" -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["provenance"]["inputs"]))' "$tmp/c/summary.json")" ]
    # a committed campaign's schema.sql reads its committed files the same way
    cp results/landing/trials.csv results/landing/summary.csv results/landing/schema.sql "$tmp/" 2>/dev/null
    (cd "$tmp" && sqlite3 landing.sqlite <schema.sql) 2>"$tmp/sql.err"
    check_that "results/landing/schema.sql runs" [ ! -s "$tmp/sql.err" ] && [ -s "$tmp/landing.sqlite" ]
    check_that "and max(steps) of results/landing is a number" [ "$(sqlite3 "$tmp/landing.sqlite" 'SELECT typeof(max(steps)) FROM trials')" = integer ]
fi
finish "cli_csv $reader"
