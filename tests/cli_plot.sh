#!/bin/sh
# footsim plot and terrain --png (issue 14 §2). Always: plot refuses (exit 2, nothing written) what
# is not a run's or a campaign's folder, a damaged trajectory or summary, and an --out it may not
# write; a run's trajectory.csv carries every spring-damper's force; a landing trial's folder
# (trial --out) carries its time series with the robot's lean, the trial unchanged by it. With gnuplot: a short run and a
# small campaign folder (a summary.json: bars with a zero rate, a one-key sweep, a two-key heat map)
# and a trial's folder give whole PNGs of the stated size (the trial's with its lean panel); terrain --png is the bare map grown by the figure's margins,
# its colour bar's pixels brightening from the lowest height to the highest. Without gnuplot those
# checks are skipped, said. Names reach gnuplot as data (issue 33): campaign files and a received
# summary.json or trajectory.csv named with quotes, line ends and gnuplot commands are drawn and run
# nothing; a gnuplot that fails is said and no success.png listed; SIGTERM, SIGHUP or SIGINT to plot
# leaves no gnuplot drawing. plot holds the folder's lock (and --out's)
# against a campaign replacing it. Usage: cli_plot.sh path/to/footsim (run from the source folder).
. "$(dirname "$0")/cli_check.sh"

# png_ok FILE: a PNG signature first, an IHDR chunk, the IEND chunk last
png_ok() {
    [ "$(od -An -tu1 -N8 "$1" | tr -s ' ')" = " 137 80 78 71 13 10 26 10" ] &&
        [ "$(od -An -c -j12 -N4 "$1" | tr -d ' ')" = "IHDR" ] &&
        [ "$(tail -c 8 "$1" | od -An -c -N4 | tr -d ' ')" = "IEND" ]
}
# png_size FILE: WxH from the IHDR chunk
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{ print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4 "x" $5 * 16777216 + $6 * 65536 + $7 * 256 + $8 }'; }
# bytes FILE
bytes() { wc -c <"$1" | tr -d ' '; }

# ---- a short run: its trajectory has the spring-damper forces ---------------------------------------
"$fs" run scenarios/static_load.ini --set run.duration_s=0.03 --out "$tmp/run" >/dev/null
check_that "the short run exits 0" [ $? -eq 0 ]
header=$(head -1 "$tmp/run/trajectory.csv")
check_that "trajectory.csv: t_s first, then the ankle, contacts, 11 hinges and 15 springs (31 columns)" \
    [ "$(echo "$header" | tr ',' '\n' | wc -l)" -eq 31 ] && [ "${header%%,*}" = t_s ]
for c in d1_chain1_N d2_chain3_N d3_chain5_N mtp5_rad; do
    check_that "trajectory.csv has $c" sh -c "echo '$header' | tr ',' '\n' | grep -qx $c"
done

# ---- refusals: exit 2, the fix named, nothing written -----------------------------------------------
mkdir -p "$tmp/empty" "$tmp/trial" "$tmp/badrun" "$tmp/badsum" "$tmp/other"
echo '{"seed": 1}' >"$tmp/trial/trial.json"
printf 'time,z\n1,2\n' >"$tmp/badrun/trajectory.csv"
echo keep >"$tmp/other/notes.txt"
expect2() { # expect2 DESCRIPTION PATTERN ARGS...: exit 2, PATTERN on stderr
    what=$1 pattern=$2
    shift 2
    "$fs" plot "$@" >"$tmp/out.txt" 2>"$tmp/err.txt"
    s=$?
    check_that "$what: exit 2 (got $s)" [ $s -eq 2 ]
    check_that "$what: says '$pattern'" grep -q "$pattern" "$tmp/err.txt"
}
expect2 "a missing folder" "No such file or directory; give the folder a run or a campaign wrote" "$tmp/none"
expect2 "a file" "not a folder; give the folder" "$tmp/trial/trial.json"
expect2 "an empty folder" "not a run's or a campaign's results (no trajectory.csv, no summary.json)" "$tmp/empty"
expect2 "a trial's folder" "trial.json holds its outcome, not a time series" "$tmp/trial"
expect2 "another CSV" "not a trajectory written by footsim run" "$tmp/badrun"
check_that "a refused folder gets nothing" [ "$(ls "$tmp/empty" "$tmp/trial" "$tmp/badrun" | grep -c 'png\|\.gp')" -eq 0 ]
# a summary whose rows are not every foot on every terrain (a cell missing)
cat >"$tmp/badsum/summary.json" <<EOF
{"campaign": "broken", "seeds": 4, "first_seed": 1, "sweep": null, "sweep2": null, "rows": [
 {"foot": "bio", "terrain": "flat", "robot": "r", "trials": 4, "landed": 4, "success_rate": 1, "ci_low": 0.5, "ci_high": 1},
 {"foot": "bio", "terrain": "rough", "robot": "r", "trials": 4, "landed": 0, "success_rate": 0, "ci_low": 0, "ci_high": 0.5},
 {"foot": "flat", "terrain": "flat", "robot": "r", "trials": 4, "landed": 2, "success_rate": 0.5, "ci_low": 0.15, "ci_high": 0.85}]}
EOF
expect2 "a summary missing a cell" "its rows are not a campaign's cells" "$tmp/badsum"
check_that "a refused summary gets no chart" [ ! -e "$tmp/badsum/chart.gp" ] && [ ! -e "$tmp/badsum/success.png" ]
expect2 "--out a folder footsim did not make" "a folder footsim did not make .*--replace" "$tmp/run" --out "$tmp/other"
check_that "--out refused: its files untouched" [ "$(ls "$tmp/other")" = notes.txt ]

# ---- a small campaign folder: a summary.json (two feet, two terrains, one rate of zero) -------------
mkdir -p "$tmp/camp" "$tmp/sweep" "$tmp/heat"
row() { # row FOOT TERRAIN LANDED [EXTRA]: a row of 4 trials with a rough interval
    printf '{"foot": "%s", "terrain": "%s", "robot": "r", "trials": 4, "landed": %d, "success_rate": %s, "ci_low": 0, "ci_high": 1, "law_prediction": "n/a"%s}' \
        "$1" "$2" "$3" "$(echo "$3" | awk '{ print $1 / 4 }')" "$4"
}
{
    echo '{"campaign": "small", "seeds": 4, "first_seed": 1, "sweep": null, "sweep2": null, "rows": ['
    echo "$(row bio flat 4), $(row bio complex_uneven 0), $(row flat flat 3), $(row flat complex_uneven 1)]}"
} >"$tmp/camp/summary.json"
{
    echo '{"campaign": "swept", "seeds": 4, "first_seed": 1, "sweep": "rough.rms_m", "sweep2": null, "rows": ['
    echo "$(row bio rough@0 4 ', "sweep_value": 0'), $(row bio rough@0.005 2 ', "sweep_value": 0.005'),"
    echo "$(row bio rough@0.01 0 ', "sweep_value": 0.01')]}"
} >"$tmp/sweep/summary.json"
{
    echo '{"campaign": "heat", "seeds": 4, "first_seed": 1, "sweep": "springs.scale", "sweep2": "robot.com_height_m", "rows": ['
    sep=
    for x in 1 10 100; do
        for h in 0.02 0.3; do
            printf '%s%s' "$sep" "$(row bio "flat@$x,$h" 2 ", \"sweep_value\": $x, \"sweep_value2\": $h, \"law_critical_com_height_m\": $(echo $x | awk '{ print 0.05 * $1 }')")"
            sep=", "
        done
    done
    echo ']}'
} >"$tmp/heat/summary.json"

# a landing trial's folder holds its time series, the robot's lean with it; the trial is the same
# with it as without
trial="$fs trial scenarios/landing_trial.ini --seed 1 --set robot.design=robots/drop_weight.ini --set run.duration_s=0.1"
$trial --out "$tmp/trial1" >/dev/null 2>&1
check_that "trial --out writes its time series" [ -s "$tmp/trial1/trajectory.csv" ]
check_that "with the robot's lean last" sh -c "head -1 '$tmp/trial1/trajectory.csv' | grep -q ',d3_chain5_N,lean_deg\$'"
$trial --json >"$tmp/plain.json" 2>/dev/null
for k in outcome end_time_s peak_force_N ankle_drop_m; do
    check_that "the trial's $k is the same with its time series kept" \
        [ "$(grep "\"$k\"" "$tmp/plain.json")" = "$(grep "\"$k\"" "$tmp/trial1/trial.json")" ]
done

if ! command -v gnuplot >/dev/null 2>&1; then
    echo "gnuplot is not installed: the plotting checks are skipped (the refusals above ran)"
    "$fs" plot "$tmp/run" 2>"$tmp/err.txt"
    check_that "no gnuplot: plot says so" grep -q 'gnuplot is not installed' "$tmp/err.txt"
    finish
    exit
fi

"$fs" plot "$tmp/run" >"$tmp/out.txt" 2>"$tmp/err.txt"
check_that "plot of a run exits 0" [ $? -eq 0 ]
check_that "plot of a run: a whole PNG" png_ok "$tmp/run/plot.png"
# five panels (drop, contacts, two of angles, springs) in three rows of 330 px under a 60 px title
check_that "plot of a run: 1200x1050 (got $(png_size "$tmp/run/plot.png"))" [ "$(png_size "$tmp/run/plot.png")" = 1200x1050 ]
check_that "plot of a run: more than 30 kB of curves, less than 5 MB" \
    [ "$(bytes "$tmp/run/plot.png")" -gt 30000 ] && [ "$(bytes "$tmp/run/plot.png")" -lt 5000000 ]
check_that "plot of a run: axes with units" grep -q "ylabel 'ankle drop (mm)'" "$tmp/run/plot.gp"
check_that "plot of a run: a line per spring-damper (15)" [ "$(grep -c 'dt [123] lc [1-5] ' "$tmp/run/plot.gp")" -ge 15 ]
"$fs" plot "$tmp/run" --out "$tmp/elsewhere" >/dev/null 2>&1
check_that "plot --out: the chart there, whole" png_ok "$tmp/elsewhere/plot.png"
"$fs" plot "$tmp/run" --out "$tmp/other" --replace >/dev/null 2>&1
check_that "plot --out --replace: the chart beside the folder's own files" png_ok "$tmp/other/plot.png" &&
    [ -f "$tmp/other/notes.txt" ]

"$fs" plot "$tmp/trial1" >/dev/null 2>&1
check_that "plot of a trial's folder: a whole PNG" png_ok "$tmp/trial1/plot.png"
check_that "plot of a trial's folder: the lean panel" grep -q "ylabel 'lean (deg)'" "$tmp/trial1/plot.gp"
# issue 32 item 4: touchdown and the deciding rule's time marked where trial.json puts them, the
# outcome and rule said (as data) on the mark and in the title
td=$(sed -n 's/.*"touchdown_s":[[:space:]]*\([-0-9.e+]*\).*/\1/p' "$tmp/trial1/trial.json")
end=$(sed -n 's/.*"end_time_s":[[:space:]]*\([-0-9.e+]*\).*/\1/p' "$tmp/trial1/trial.json")
said=$(sed -n 's/.*"outcome":[[:space:]]*"\([a-z_]*\)".*/\1/p' "$tmp/trial1/trial.json")
rule=$(sed -n 's/.*"rule":[[:space:]]*"\([a-z_]*\)".*/\1/p' "$tmp/trial1/trial.json")
check_that "plot of a trial: touchdown marked at $td s" awk -v t="$td" '/^set arrow 1 from/ { split($5, a, ","); d = a[1] - t; ok = d < 1e-6 && d > -1e-6 } END { exit !ok }' "$tmp/trial1/plot.gp"
check_that "plot of a trial: its decision marked at $end s" awk -v t="$end" '/^set arrow 2 from/ { split($5, a, ","); d = a[1] - t; ok = d < 1e-6 && d > -1e-6 } END { exit !ok }' "$tmp/trial1/plot.gp"
check_that "plot of a trial: the outcome '$said ($rule)' said" grep -q "^decided = '$said ($rule)'" "$tmp/trial1/plot.gp"
check_that "plot of a trial: the title names the seed and the outcome" grep -q "seed 1: $said ($rule)" "$tmp/trial1/plot.gp"

for d in camp sweep heat; do
    "$fs" plot "$tmp/$d" >"$tmp/out.txt" 2>"$tmp/err.txt"
    check_that "plot of campaign folder $d exits 0" [ $? -eq 0 ]
    check_that "plot of campaign folder $d: a whole PNG" png_ok "$tmp/$d/success.png"
    check_that "plot of campaign folder $d: more than 10 kB" [ "$(bytes "$tmp/$d/success.png")" -gt 10000 ]
done
check_that "bars: 960x540 (got $(png_size "$tmp/camp/success.png"))" [ "$(png_size "$tmp/camp/success.png")" = 960x540 ]
check_that "bars: a rate of zero drawn under the zero line" grep -q '== 0 ? -0.025' "$tmp/camp/chart.gp"
check_that "bars: every cell's rate in the data" [ "$(grep -c '^"' "$tmp/camp/chart.dat")" -eq 2 ]
# a heat-map panel: 560x480, the map over a legend of the laws (issue 34 item 5)
check_that "heat map: one panel, 560x480 (got $(png_size "$tmp/heat/success.png"))" [ "$(png_size "$tmp/heat/success.png")" = 560x480 ]
# both laws' lines drawn against the height (columns 9 and 11 of chart.dat), each keyed
check_that "heat map: the static law's critical height drawn and keyed" \
    grep -q 'using 1:9 with lines lw 2 lc' "$tmp/heat/chart.gp" && grep -q "title 'its critical height K/(m g)'" "$tmp/heat/chart.gp"
check_that "heat map: the drop law's highest centre of mass drawn dashed and keyed" \
    grep -q 'using 1:11 with lines lw 2 dt 2' "$tmp/heat/chart.gp" && grep -q "title 'its highest centre of mass'" "$tmp/heat/chart.gp"
check_that "heat map: the drop law's column in the data (11 fields a cell)" \
    [ "$(grep -v '^#' "$tmp/heat/chart.dat" | awk 'NF { print NF }' | sort -u)" = 11 ]
# issue 32 item 4: bars grouped by robot, each foot in one colour whatever the robot, the law marked
mkdir -p "$tmp/grouped"
law() { printf '{"foot": "%s", "terrain": "flat", "robot": "%s", "trials": 4, "landed": 2, "success_rate": 0.5, "ci_low": 0.15, "ci_high": 0.85, "law_prediction": "%s"}' "$1" "$2" "$3"; }
echo "{\"campaign\": \"grouped\", \"seeds\": 4, \"first_seed\": 1, \"sweep\": null, \"sweep2\": null, \"rows\": [$(law bio r1 stands), $(law bio r2 topples), $(law flat r1 stands), $(law flat r2 none)]}" >"$tmp/grouped/summary.json"
"$fs" plot "$tmp/grouped" >/dev/null 2>&1
check_that "grouped bars: a whole PNG" png_ok "$tmp/grouped/success.png"
# the series are foot-major (bio r1, bio r2, flat r1, flat r2): their rate's boxes in the foot's colour
boxes=$(grep -o "using (\$0[-+.0-9]*):[0-9]* with boxes fs solid [0-9.]* lc [0-9]* title series[0-9]" "$tmp/grouped/chart.gp")
check_that "grouped bars: each foot one colour (bio 1, flat 2)" \
    [ "$(echo "$boxes" | sed 's/.* lc \([0-9]*\) title series\([0-9]\)/\2:\1/' | tr '\n' ' ')" = "1:1 2:1 3:2 4:2 " ]
offs=$(echo "$boxes" | sed 's/using (\$0\([-+.0-9]*\)).*/\1/' | tr '\n' ' ')
check_that "grouped bars: robot by robot (bio r1 < flat r1 < bio r2 < flat r2: $offs)" \
    sh -c "echo '$offs' | awk '{ exit !(\$1 < \$3 && \$3 < \$2 && \$2 < \$4) }'"
check_that "grouped bars: the law's verdict in the data (1 stands, 0 topples, -1 none)" \
    [ "$(grep -v '^#' "$tmp/grouped/chart.dat" | awk '{ print $5, $9, $13, $17 }')" = "1 0 1 -1" ]
check_that "grouped bars: the law marked (o stands, x topples) and keyed" \
    sh -c "[ \$(grep -c 'with points pt 6' '$tmp/grouped/chart.gp') -ge 5 ] && grep -q \"title 'law: topples'\" '$tmp/grouped/chart.gp'"

# ---- names reach gnuplot as data, never as code (issue 33, item 4) --------------------------------------
# campaign files named with a quote, a gnuplot command and a newline: each drawn, nothing run
. "$(dirname "$0")/small_campaign.sh"
# the flat foot alone: nothing here reads the biomimetic foot's results, and a campaign with it works
# out the arch's fold moment for the drop law (about 3 s of CPU, several times that under the sanitizers)
sed -i '/^\[foot.bio\]/,/^$/d' "$tmp/small.ini"
mkdir -p "$tmp/names"
nl='
'
i=0
for name in "bob's campaign" "x'; system('touch INJECTED'); y='" "two${nl}lines" 'back\slash`touch INJECTED`@x'; do
    i=$((i + 1))
    cp "$tmp/small.ini" "$tmp/$name.ini"
    (cd "$tmp" && "$fs" campaign "$name.ini" --set campaign.seeds=1 --set run.duration_s=0.1 --out "$tmp/names/out$i") \
        >"$tmp/out.txt" 2>"$tmp/err.txt"
    check_that "campaign file '$name': exit 0" [ $? -eq 0 ]
    check_that "campaign file '$name': a whole success.png" png_ok "$tmp/names/out$i/success.png"
    check_that "campaign file '$name': nothing run" [ -z "$(find "$tmp" -name INJECTED)" ]
    check_that "campaign file '$name': gnuplot said nothing" [ -z "$(grep -v 'trials done' "$tmp/err.txt")" ]
done
# a received summary.json whose every name is hostile: drawn, nothing run
mkdir -p "$tmp/hostile_bars" "$tmp/hostile_sweep"
# (printf, not echo: dash's echo would read the backslashes)
evil='\u0027; system(\"touch INJECTED\"); x=\u0027 \n `touch INJECTED` @x \\'
{
    printf '%s\n' "{\"campaign\": \"'; system(\\\"touch INJECTED\\\")\", \"seeds\": 4, \"first_seed\": 1, \"sweep\": null, \"sweep2\": null, \"rows\": ["
    printf '%s\n' "$(row "bio$evil" "flat$evil" 4), $(row "bio$evil" 'rou\"gh' 0), $(row flat "flat$evil" 3), $(row flat 'rou\"gh' 1)]}"
} >"$tmp/hostile_bars/summary.json"
{
    printf '%s\n' "{\"campaign\": \"s$evil\", \"seeds\": 4, \"first_seed\": 1, \"sweep\": \"rough.rms_m$evil\", \"sweep2\": null, \"rows\": ["
    printf '%s\n' "$(row "bio$evil" rough@0 4 ', "sweep_value": 0'), $(row "bio$evil" rough@0.005 2 ', "sweep_value": 0.005')]}"
} >"$tmp/hostile_sweep/summary.json"
for d in hostile_bars hostile_sweep heat; do
    "$fs" plot "$tmp/$d" >"$tmp/out.txt" 2>"$tmp/err.txt"
    check_that "plot of $d: exit 0" [ $? -eq 0 ]
    check_that "plot of $d: a whole success.png" png_ok "$tmp/$d/success.png"
    # (a name ending in a backslash draws a warning from gnuplot's measure of a rotated tic label)
    check_that "plot of $d: gnuplot found no error" [ -z "$(grep -v 'warning: enhanced text parser' "$tmp/err.txt")" ]
done
check_that "hostile summaries: nothing run" [ -z "$(find "$tmp" -name INJECTED)" ]
check_that "hostile summaries: chart.dat keeps its columns (5 fields a terrain)" \
    [ "$(grep -v '^#' "$tmp/hostile_bars/chart.dat" | awk -F'"' '{ print NF }' | sort -u)" = 3 ]
# a trajectory.csv whose columns are named to run a command
mkdir -p "$tmp/hostile_run"
sed "1s/mtp1_rad/mtp'.system(\"touch INJECTED\").'_rad/; 1s/ankle_x_m/x'; system('touch INJECTED'); y='_rad/" \
    "$tmp/run/trajectory.csv" >"$tmp/hostile_run/trajectory.csv"
"$fs" plot "$tmp/hostile_run" >"$tmp/out.txt" 2>"$tmp/err.txt"
check_that "plot of a hostile trajectory: exit 0, a whole PNG" png_ok "$tmp/hostile_run/plot.png"
check_that "plot of a hostile trajectory: nothing run" [ -z "$(find "$tmp" -name INJECTED)" ]

# gnuplot failing: no success.png listed, the message naming the folder the results are in
mkdir -p "$tmp/badgp"
printf '#!/bin/sh\necho "gnuplot broke" >&2\nexit 1\n' >"$tmp/badgp/gnuplot"
chmod +x "$tmp/badgp/gnuplot"
PATH="$tmp/badgp:$PATH" "$fs" campaign "$tmp/small.ini" --set campaign.seeds=1 --set run.duration_s=0.1 --out "$tmp/nochart" \
    >"$tmp/out.txt" 2>"$tmp/err.txt"
check_that "gnuplot failing: the campaign's results still written" [ -s "$tmp/nochart/summary.json" ] && [ ! -e "$tmp/nochart/success.png" ]
check_that "gnuplot failing: success.png not listed" sh -c "! grep -q 'success.png\$' '$tmp/out.txt'"
check_that "gnuplot failing: said, naming the results folder, not a partial one" \
    grep -q "gnuplot failed: no chart $tmp/nochart/success.png (the data and script chart.gp are in $tmp/nochart)" "$tmp/err.txt"
PATH="$tmp/badgp:$PATH" "$fs" plot "$tmp/camp" --out "$tmp/nochart_plot" >"$tmp/out.txt" 2>"$tmp/err.txt"
check_that "gnuplot failing: plot exits 4, lists nothing" [ $? -eq 4 ] && [ ! -s "$tmp/out.txt" ] && [ ! -e "$tmp/nochart_plot/success.png" ]

# ---- plot holds the folders it reads and writes (issue 33, item 7) ----------------------------------
# another footsim's lock on the folder (as a campaign replacing it holds): plot refuses, writes nothing
rm -f "$tmp/camp/success.png"
echo $$ >"$tmp/.camp.footsim-lock"
flock "$tmp/.camp.footsim-lock" sleep 30 &
holder=$!
sleep 1
"$fs" plot "$tmp/camp" >"$tmp/out.txt" 2>"$tmp/err.txt"
check_that "a held folder: plot exits 2" [ $? -eq 2 ]
check_that "a held folder: said" grep -q "plot $tmp/camp: another footsim (process $$) is writing this folder" "$tmp/err.txt"
check_that "a held folder: no chart" [ ! -e "$tmp/camp/success.png" ]
kill $holder
wait $holder 2>/dev/null
# a plot holding its folder (delayed between taking the lock and reading): a campaign for that
# folder started meanwhile is refused, and the plot completes
"$fs" campaign "$tmp/small.ini" --set campaign.seeds=1 --set run.duration_s=0.1 --out "$tmp/held" >/dev/null 2>&1
FOOTSIM_TEST_PLOT_DELAY=3 "$fs" plot "$tmp/held" >"$tmp/plot_held.txt" 2>&1 &
plotter=$!
sleep 1
"$fs" campaign "$tmp/small.ini" --set campaign.seeds=2 --set run.duration_s=0.1 --out "$tmp/held" >"$tmp/out.txt" 2>"$tmp/err.txt"
check_that "a campaign on a folder plot holds: exit 2" [ $? -eq 2 ]
check_that "a campaign on a folder plot holds: said" grep -q "another footsim (process $plotter) is writing this folder" "$tmp/err.txt"
wait $plotter
check_that "the plot holding it: exit 0, a whole chart" [ $? -eq 0 ] && png_ok "$tmp/held/success.png"
check_that "the plot holding it: the folder still the first campaign's" grep -q '"seeds":	1' "$tmp/held/summary.json"
check_that "the plot's lock released" [ ! -e "$tmp/.held.footsim-lock" ]

# ---- killing plot takes gnuplot with it (issue 33, item 10) -----------------------------------------
# a trajectory of 20000 rows (the short run's rows repeated): gnuplot draws it for seconds; plot is
# killed by SIGTERM, SIGHUP and SIGINT while it does; gnuplot must be gone (or a zombie of init's)
# and no temporary chart left
mkdir -p "$tmp/big"
awk -F, 'NR == 1 { print; next } { row[++n] = $0 }
    END { for (i = 0; i < 20000; i++) { r = row[1 + i % n]; sub(/^[^,]*/, i * 1e-4, r); print r } }' \
    "$tmp/run/trajectory.csv" >"$tmp/big/trajectory.csv"
alive() { s=$(ps -o stat= -p "$1" 2>/dev/null); [ -n "$s" ] && [ "${s#Z}" = "$s" ]; }
# a background job of a script has SIGINT ignored (and footsim keeps it so): env restores it
default_int=
env --default-signal=INT true 2>/dev/null && default_int="env --default-signal=INT"
for sig in TERM:15 HUP:1 INT:2; do
    num=${sig#*:} sig=${sig%:*}
    [ $sig = INT ] && [ -z "$default_int" ] && { echo "env --default-signal is missing: SIGINT not tried"; continue; }
    $default_int "$fs" plot "$tmp/big" >/dev/null 2>"$tmp/kill_$sig.err" &
    plotter=$!
    gp=
    for i in $(seq 150); do
        gp=$(pgrep -P $plotter -x gnuplot) && break
        sleep 0.1
    done
    check_that "SIG$sig: gnuplot was drawing" [ -n "$gp" ]
    kill -$sig $plotter
    wait $plotter
    status=$?
    check_that "SIG$sig: plot ended by it (status $status)" [ $status -eq $((128 + num)) ]
    for i in $(seq 50); do
        alive "$gp" || break
        sleep 0.1
    done
    check_that "SIG$sig: no gnuplot left drawing" sh -c "! { ps -o stat= -p '$gp' | grep -qv '^Z'; }"
    [ -n "$gp" ] && kill -9 "$gp" 2>/dev/null
    check_that "SIG$sig: no temporary chart left" [ -z "$(ls -A "$tmp/big" | grep tmp)" ]
    check_that "SIG$sig: no half chart" [ ! -e "$tmp/big/plot.png" ]
done

# ---- terrain's summary over a scenario's region: the region the picture shows, said ------------------
"$fs" terrain terrains/complex_uneven.ini >"$tmp/plain.txt"
"$fs" terrain terrains/complex_uneven.ini --scenario scenarios/landing_trial.ini >"$tmp/scen.txt"
"$fs" terrain terrains/complex_uneven.ini --scenario scenarios/landing_trial.ini --png "$tmp/scen.png" >"$tmp/scen_png.txt"
region() { grep -o 'over x [-0-9.]*\.\.[-0-9.]* m, y [-0-9.]*\.\.[-0-9.]* m' "$1" | sed 's/^over //'; }
check_that "terrain --scenario: the summary names the scenario's region" grep -q "what the scenario's foot reaches, and its margin" "$tmp/scen.txt"
check_that "terrain --scenario: its region is not the default one" [ "$(region "$tmp/scen.txt")" != "$(region "$tmp/plain.txt")" ]
# a walk reaches along its path: [walk] steps x step_length_m (walking.ini: 8 x 0.06 m) past the start
"$fs" terrain terrains/stepped.ini --scenario scenarios/walking.ini >"$tmp/walk.txt"
walk_xmax=$(region "$tmp/walk.txt" | sed 's/^x [-0-9.]*\.\.\([-0-9.]*\) m.*/\1/')
check_that "terrain --scenario with a walk: the region runs along its path (x to $walk_xmax m)" \
    awk -v x="$walk_xmax" 'BEGIN { exit !(x > 0.48) }'
check_that "terrain --scenario: the summary and the picture cover the same region" \
    [ "$(region "$tmp/scen.txt")" = "$(grep -o 'over x [-0-9.]*\.\.[-0-9.]* m, y [-0-9.]*\.\.[-0-9.]* m' "$tmp/scen_png.txt" | sed 's/^over //')" ]

# ---- terrain --png: the bare map without gnuplot, the figure with it ----------------------------------
mkdir -p "$tmp/nognuplot"
PATH="$tmp/nognuplot" "$fs" terrain terrains/complex_uneven.ini --png "$tmp/bare.png" >/dev/null 2>"$tmp/err.txt"
check_that "terrain --png without gnuplot: exit 0, the bare map, said" png_ok "$tmp/bare.png" &&
    grep -q 'the bare map, without axes or colour bar' "$tmp/err.txt"
"$fs" terrain terrains/flat.ini --png "$tmp/flat.png" >"$tmp/out.txt" 2>&1
check_that "terrain --png of level ground: a figure too (a bar 1 mm up from its height)" grep -q 'axes and colour bar in mm' "$tmp/out.txt"
"$fs" terrain terrains/complex_uneven.ini --png "$tmp/fig.png" >"$tmp/out.txt"
check_that "terrain --png exits 0 and says axes in mm" grep -q 'axes and colour bar in mm' "$tmp/out.txt"
check_that "terrain --png: a whole PNG" png_ok "$tmp/fig.png"
bw=$(png_size "$tmp/bare.png" | cut -dx -f1) bh=$(png_size "$tmp/bare.png" | cut -dx -f2)
fw=$(png_size "$tmp/fig.png" | cut -dx -f1) fh=$(png_size "$tmp/fig.png" | cut -dx -f2)
# margins: 80 px left (y axis), 130 px right (colour bar), 60 px under (x axis), 50 px over (title)
check_that "terrain --png: the map grown by the margins (${bw}x$bh -> ${fw}x$fh)" [ $((fw - bw)) -eq 210 ] && [ $((fh - bh)) -eq 110 ]
# the colour bar: 20 px right of the map, 22 px wide, as tall as the map; its middle column from the
# bottom up, a pixel in from each end, gets brighter (the ramp's R+G+B rises 210 -> 710)
x=$((80 + bw + 20 + 11))
gnuplot -e "set table '$tmp/bar.txt'; plot '$tmp/fig.png' binary filetype=png every 1:1:$x:0:$x:$((fh - 1)) using 1:2:3 with table" 2>/dev/null
awk -v lo=$((60 + 2)) -v hi=$((60 + bh - 3)) '$2 >= lo && $2 <= hi { print $2, $3 + $4 + $5 }' "$tmp/bar.txt" | sort -n >"$tmp/bar.sum"
check_that "colour bar: $(wc -l <"$tmp/bar.sum") pixels read" [ "$(wc -l <"$tmp/bar.sum")" -gt $((bh - 10)) ]
check_that "colour bar: brighter from bottom to top, by more than 300 (R+G+B)" \
    awk 'NR == 1 { first = $2 } NR > 1 && $2 < prev - 3 { bad = 1 } { prev = $2 } END { exit bad || prev - first <= 300 }' "$tmp/bar.sum"

finish
