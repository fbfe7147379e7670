#!/bin/sh
# Issue 16, findings 1, 5 and 10: footsim replaces only results folders it made (its marker, issue 33
# item 3), refuses anything else at --out before simulating (exit 2), normalises the path, holds a
# lock while writing, and swaps safely where renameat2(RENAME_EXCHANGE) is refused. Every target is made here, in $tmp.
# Usage: cli_outdir.sh path/to/footsim (run from the source folder).
. "$(dirname "$0")/cli_check.sh"
src=$PWD
case $fs in /*) ;; *) fs=$PWD/$fs ;; esac
short="--set run.duration_s=0.02"
# finding 1: a folder holding the user's files (the reproducer: scenarios/, terrains/, notes.txt)
mkdir -p "$tmp/thesis/scenarios/feet" "$tmp/thesis/terrains"
cp scenarios/static_load.ini "$tmp/thesis/scenarios/" && cp scenarios/feet/*.ini "$tmp/thesis/scenarios/feet/"
cp terrains/flat.ini "$tmp/thesis/terrains/" && echo "my notes" >"$tmp/thesis/notes.txt"
(cd "$tmp/thesis" && "$fs" run scenarios/static_load.ini $short --out "$PWD" >/dev/null 2>"$tmp/err1")
s1=$?
check '[ "$s1" -eq 2 ] && grep -q "a folder footsim did not make" "$tmp/err1"'
(cd "$tmp/thesis" && "$fs" run scenarios/static_load.ini $short --out scenarios >/dev/null 2>/dev/null)
s2=$?
check '[ "$s2" -eq 2 ] && [ -f "$tmp/thesis/notes.txt" ] && [ -f "$tmp/thesis/scenarios/static_load.ini" ]'
check '[ -f "$tmp/thesis/terrains/flat.ini" ] && [ ! -e "$tmp/thesis/metrics.json" ]'
check '[ -z "$(ls -a "$tmp/thesis" | grep -e partial -e lock)" ]'
# campaign and render-compare refuse it the same way, before any trial or frame
"$fs" campaign scenarios/landing_ci.ini --set campaign.seeds=1 -j 1 --out "$tmp/thesis" >/dev/null 2>"$tmp/err2"
s3=$?
check '[ "$s3" -eq 2 ] && grep -q "did not make" "$tmp/err2" && [ -f "$tmp/thesis/notes.txt" ]'
# benches write file by file into their folder and never replace it: a folder of the user's is refused
"$fs" bench speed --quick --out "$tmp/thesis" >/dev/null 2>"$tmp/errb"
sb=$?
check '[ "$sb" -eq 2 ] && grep -q "writes into only its own results folders" "$tmp/errb" && [ -f "$tmp/thesis/notes.txt" ]'
# --replace replaces it on purpose
mkdir "$tmp/mine" && echo x >"$tmp/mine/notes.txt"
"$fs" run scenarios/static_load.ini $short --out "$tmp/mine" --replace >/dev/null
check '[ -f "$tmp/mine/metrics.json" ] && [ ! -e "$tmp/mine/notes.txt" ] && [ -f "$tmp/mine/.footsim-results" ]'
# issue 33 item 3: a folder is footsim's by its marker only, never by its files' names: a folder
# holding files named as footsim names its own (a user's draft summary.md, metrics.json,
# trajectory.csv; an earlier version's folder without the marker) is read, not replaced: exit 2,
# every file kept, nothing written beside it; --replace replaces it on purpose
mkdir "$tmp/named" && echo draft >"$tmp/named/summary.md"
expect 2 "a folder footsim did not make (it has no .footsim-results marker, whatever its files are called).*--replace" \
    -- campaign scenarios/landing_ci.ini --set campaign.seeds=1 -j 1 --out "$tmp/named"
check '[ "$(cat "$tmp/named/summary.md")" = draft ] && [ "$(ls -A "$tmp/named")" = summary.md ]'
mkdir "$tmp/old" && echo '{"mine": 1}' >"$tmp/old/metrics.json" && echo t >"$tmp/old/trajectory.csv"
expect 2 "a folder footsim did not make" -- run scenarios/static_load.ini $short --out "$tmp/old"
check '[ "$(cat "$tmp/old/metrics.json")" = "{\"mine\": 1}" ] && [ "$(cat "$tmp/old/trajectory.csv")" = t ] && [ ! -e "$tmp/old/.footsim-results" ]'
mkdir -p "$tmp/oldf/frames" && echo '{}' >"$tmp/oldf/trial.json" && echo p >"$tmp/oldf/frames/000000.png"
expect 2 "a folder footsim did not make" -- trial scenarios/landing_trial.ini --set run.duration_s=0.05 --out "$tmp/oldf"
check '[ -f "$tmp/oldf/frames/000000.png" ] && [ -z "$(ls -a "$tmp" | grep -e "partial" -e "lock")" ]'
"$fs" run scenarios/static_load.ini $short --out "$tmp/old" --replace >/dev/null
check '[ -f "$tmp/old/.footsim-results" ] && grep -q ankle_drop_m "$tmp/old/metrics.json"'
# an empty folder is fine
mkdir "$tmp/empty"
"$fs" run scenarios/static_load.ini $short --out "$tmp/empty" >/dev/null
check '[ -f "$tmp/empty/metrics.json" ]'
# finding 5: a trailing slash, "/./" and a scenario named "..ini" are put in place or refused up front
"$fs" run scenarios/static_load.ini $short --out "$tmp/slash/" >/dev/null
s4=$?
check '[ "$s4" -eq 0 ] && [ -f "$tmp/slash/metrics.json" ]'
"$fs" run scenarios/static_load.ini $short --out "$tmp/slash/./" >/dev/null
s5=$?
check '[ "$s5" -eq 0 ] && [ -f "$tmp/slash/metrics.json" ] && [ -z "$(ls -a "$tmp/slash" | grep partial)" ]'
mkdir "$tmp/dots" && cp scenarios/static_load.ini "$tmp/dots/..ini"
sed -i "s|^design = .*|design = $src/scenarios/feet/biomimetic.ini|; s|^terrain = .*|terrain = $src/terrains/flat.ini|" "$tmp/dots/..ini"
(cd "$tmp/dots" && "$fs" run ..ini $short >/dev/null 2>"$tmp/err3")
s6=$?
check '[ "$s6" -eq 2 ] && grep -q "give --out" "$tmp/err3"'
# finding 10: a symbolic link, a regular file, a FIFO at --out are refused, and left as they were
mkdir "$tmp/target" && echo keep >"$tmp/target/keep.txt" && ln -s "$tmp/target" "$tmp/link"
"$fs" run scenarios/static_load.ini $short --out "$tmp/link" --replace >/dev/null 2>"$tmp/err4"
s7=$?
check '[ "$s7" -eq 2 ] && grep -q "symbolic link" "$tmp/err4" && [ -L "$tmp/link" ] && [ -f "$tmp/target/keep.txt" ]'
echo data >"$tmp/file" && mkfifo "$tmp/fifo"
"$fs" run scenarios/static_load.ini $short --out "$tmp/file" >/dev/null 2>"$tmp/err5"
s8=$?
check '[ "$s8" -eq 2 ] && grep -q "is a regular file, not a results folder" "$tmp/err5" && [ "$(cat "$tmp/file")" = data ]'
"$fs" run scenarios/static_load.ini $short --out "$tmp/fifo" >/dev/null 2>"$tmp/err6"
s9=$?
check '[ "$s9" -eq 2 ] && grep -q "is a FIFO" "$tmp/err6" && [ -p "$tmp/fifo" ]'
# terrain --png never replaces a symbolic link, a FIFO or a device node
"$fs" terrain terrains/flat.ini --png "$tmp/fifo" >/dev/null 2>"$tmp/err7"
s10=$?
check '[ "$s10" -eq 2 ] && grep -q "is a FIFO" "$tmp/err7" && [ -p "$tmp/fifo" ]'
ln -s "$tmp/file" "$tmp/pnglink"
"$fs" terrain terrains/flat.ini --png "$tmp/pnglink" >/dev/null 2>/dev/null
s11=$?
check '[ "$s11" -eq 2 ] && [ -L "$tmp/pnglink" ] && [ "$(cat "$tmp/file")" = data ]'
# a user's file that is not a PNG is not replaced by one (exit 2, the fix named) unless --replace;
# a PNG (footsim's earlier picture) is
echo "thesis notes" >"$tmp/notes.txt"
expect 2 "the file exists and is not a PNG.*give another name, remove it, or add --replace" -- terrain terrains/flat.ini --png "$tmp/notes.txt"
check '[ "$(cat "$tmp/notes.txt")" = "thesis notes" ]'
"$fs" terrain terrains/flat.ini --png "$tmp/map.png" >/dev/null 2>&1 && "$fs" terrain terrains/rough.ini --png "$tmp/map.png" >/dev/null 2>"$tmp/err13"
s13=$?
check '[ "$s13" -eq 0 ] && [ "$(head -c 4 "$tmp/map.png" | tail -c 3)" = PNG ]'
"$fs" terrain terrains/flat.ini --png "$tmp/notes.txt" --replace >/dev/null 2>"$tmp/err14"
s14=$?
check '[ "$s14" -eq 0 ] && [ "$(head -c 4 "$tmp/notes.txt" | tail -c 3)" = PNG ]'
if mknod "$tmp/null" c 1 3 2>/dev/null; then
    "$fs" terrain terrains/flat.ini --png "$tmp/null" >/dev/null 2>"$tmp/err8"
    s12=$?
    check '[ "$s12" -eq 2 ] && grep -q "character device" "$tmp/err8" && [ -c "$tmp/null" ]'
else
    echo "skipped: mknod is not allowed here (the device-node case of finding 10)"
fi
# the lock: a second footsim writing the same folder is refused while the first holds it
mkdir "$tmp/locked"
if command -v flock >/dev/null; then
    # flock(1) holds the lock until told to stop; "held" appears once it has it
    flock "$tmp/.locked.footsim-lock" sh -c "touch '$tmp/held'; while [ ! -e '$tmp/release' ]; do sleep 0.1; done" &
    holder=$!
    for i in $(seq 300); do [ -e "$tmp/held" ] && break; sleep 0.1; done
    "$fs" run scenarios/static_load.ini $short --out "$tmp/locked" >/dev/null 2>"$tmp/err9"
    s13=$?
    touch "$tmp/release"
    check '[ "$s13" -eq 2 ] && grep -q "another footsim" "$tmp/err9" && [ ! -e "$tmp/locked/metrics.json" ]'
    wait $holder
else
    echo "skipped: no flock(1) to hold the lock (the lock case)"
fi
# where renameat2(RENAME_EXCHANGE) is refused (EINVAL on NFS), the two-rename swap still replaces whole
FOOTSIM_TEST_NO_EXCHANGE=1 "$fs" run scenarios/static_load.ini $short --set load.mass_kg=5 --out "$tmp/mine" >/dev/null
check 'grep -q "\"load_kg\":[[:space:]]*5" "$tmp/mine/metrics.json" && [ -z "$(ls -a "$tmp" | grep -e "mine\.old" -e "mine\.partial")" ]'
# leftovers of a killed run (partial and old folders beside it, marked or empty) are cleared by the
# next run; a user's folder of a like name ("mine.old.2024", with their files) is left alone
mkdir "$tmp/mine.partial.99999" "$tmp/mine.old.99998" "$tmp/mine.old.2024"
echo "mine" >"$tmp/mine.old.2024/notes.txt" && cp "$tmp/mine/.footsim-results" "$tmp/mine.partial.99999/"
"$fs" run scenarios/static_load.ini $short --out "$tmp/mine" >/dev/null
check '[ -z "$(ls -a "$tmp" | grep -e "mine\.old\.9" -e "mine\.partial")" ] && [ -f "$tmp/mine/metrics.json" ]'
check '[ -f "$tmp/mine.old.2024/notes.txt" ]'
# a file of the user's where the lock would go is not footsim's to write: refused, left as it was
echo "my notes" >"$tmp/.lk.footsim-lock"
"$fs" run scenarios/static_load.ini $short --out "$tmp/lk" >/dev/null 2>"$tmp/errl"
sl=$?
check '[ "$sl" -eq 2 ] && grep -q "is not footsim.s lock file" "$tmp/errl" && [ "$(cat "$tmp/.lk.footsim-lock")" = "my notes" ]'
# issue 33 item 3 for plot --out: files named as plot names its own (plot.gp, chart.dat) are the user's
"$fs" run scenarios/static_load.ini $short --out "$tmp/r" >/dev/null
mkdir "$tmp/charts" && echo mine >"$tmp/charts/plot.gp" && echo data >"$tmp/charts/chart.dat"
expect 2 "a folder footsim did not make" -- plot "$tmp/r" --out "$tmp/charts"
check '[ "$(cat "$tmp/charts/plot.gp")" = mine ] && [ "$(cat "$tmp/charts/chart.dat")" = data ]'

# issue 33 item 1: a path is never cut short (long_dir: cli_check.sh)
# the issue's case: a 1083-character folder D; --out D/res, then --out D/res_v2_experiment (which an
# unchecked 1088-byte buffer cut to D/res) leaves D/res as it was
D=$(long_dir 1083 d)
mkdir -p "$D"
check '[ ${#D} -eq 1083 ]'
"$fs" run scenarios/static_load.ini $short --out "$D/res" >/dev/null
"$fs" run scenarios/static_load.ini $short --set load.mass_kg=5 --out "$D/res_v2_experiment" >/dev/null
check 'grep -q "\"load_kg\":[[:space:]]*5" "$D/res_v2_experiment/metrics.json" && ! grep -q "\"load_kg\":[[:space:]]*5" "$D/res/metrics.json"'
# a path that fits within PATH_MAX with room for .partial.<pid> and the rest (3500 characters) works
F=$(long_dir 3500 f)
"$fs" run scenarios/static_load.ini $short --out "$F" >/dev/null
check '[ -f "$F/metrics.json" ] && [ -z "$(ls -a "${F%/*}" | grep -e partial -e lock)" ]'
"$fs" trial scenarios/landing_trial.ini --set run.duration_s=0.05 --out "$F.t" >/dev/null
check '[ -f "$F.t/trial.json" ]'
"$fs" walk scenarios/walking.ini --set walk.steps=1 --out "$F.w" >/dev/null
check '[ -f "$F.w/walk.json" ]'
"$fs" terrain terrains/flat.ini --png "$F.png" >/dev/null
check '[ -f "$F.png" ]'
"$fs" plot "$tmp/r" --out "$F.p" >/dev/null 2>&1
check '[ -f "$F.p/.footsim-results" ]'
# one too long (4080 characters), or with a name longer than NAME_MAX, is refused before anything
# runs (exit 2, what is wrong and what would be right), nothing written, by every command that writes
L=$(long_dir 4080 g)
N=$tmp/$(printf "%0240d" 0 | tr 0 h)
for target in "$L" "$N"; do
    expect 2 "--out .*: the .* is [0-9]* characters long; .* at most [0-9]*.*give a shorter" -- run scenarios/static_load.ini $short --out "$target"
    expect 2 "--out .*characters long" -- trial scenarios/landing_trial.ini --out "$target"
    expect 2 "--out .*characters long" -- walk scenarios/walking.ini --out "$target"
    expect 2 "--out .*characters long" -- campaign scenarios/landing_ci.ini --out "$target"
    expect 2 "--out .*characters long" -- optimize scenarios/optimize_single_tall.ini --out "$target"
    expect 2 "--out .*characters long" -- plot "$tmp/r" --out "$target"
    expect 2 "--png .*characters long" -- terrain terrains/flat.ini --png "$target"
    expect 2 "--out .*characters long" -- export scenarios/feet/biomimetic.ini --mjcf --out "$target"
    "$fs" render-compare scenarios/static_load.ini scenarios/tilt10.ini --out "$target" >/dev/null 2>&1
    check "[ \$? -eq 2 ]"
    check '[ ! -e "$tmp/gggg" ] && [ -z "$(ls "$tmp" | grep -e "^g" -e "^hhh")" ]'
done
# an input file's path too long to keep whole is refused so, not cut short to another file
expect 2 "x.ini: the path is [0-9]* characters long; footsim takes at most [0-9]* here: give a shorter path" -- run "$N/${N##*/}/${N##*/}/${N##*/}/${N##*/}/x.ini"
# issue 33 item 14: an empty path is refused as such (exit 2), not "footsim: : cannot replace"
expect 2 "--png '': an empty path; give a path" -- terrain terrains/flat.ini --png ""

# issue 33 item 13: a results folder footsim made that cannot be removed whole (immutable, which
# even root cannot remove; read-only for a user) is refused before anything runs: exit 4, the folder
# named and what to do, the old results and nothing else left
"$fs" run scenarios/static_load.ini $short --out "$tmp/ro" >/dev/null
cp "$tmp/ro/metrics.json" "$tmp/ro.before"
trap 'chattr -R -i "$tmp" 2>/dev/null; rm -rf "$tmp"' EXIT
if chattr +i "$tmp/ro/metrics.json" 2>/dev/null; then
    expect 4 "--out .*ro: cannot be replaced: .*ro/metrics.json is immutable (chattr +i); make it writable" -- run scenarios/static_load.ini $short --out "$tmp/ro"
    check 'cmp -s "$tmp/ro.before" "$tmp/ro/metrics.json" && [ -z "$(ls -a "$tmp" | grep -e "ro\.partial" -e "ro\.old" -e "\.ro\.footsim-lock")" ]'
    chattr -i "$tmp/ro/metrics.json" && chattr +i "$tmp/ro"
    expect 4 "--out .*ro: cannot be replaced: .*ro is immutable" -- run scenarios/static_load.ini $short --out "$tmp/ro"
    check '[ -z "$(ls -a "$tmp" | grep -e "ro\.partial" -e "ro\.old" -e "\.ro\.footsim-lock")" ]'
    chattr -i "$tmp/ro"
else
    echo "skipped: chattr +i is refused here (the immutable-folder case of issue 33 item 13)"
fi
# the issue's case, a folder made read-only (chmod a-w), as a user (root writes it anyway: as root,
# the run is made as nobody with setpriv, in a folder nobody owns)
as_user=""
if [ "$(id -u)" -eq 0 ] && command -v setpriv >/dev/null; then
    as_user="setpriv --reuid=65534 --regid=65534 --clear-groups"
    chmod 755 "$tmp" && mkdir "$tmp/user" && chown 65534:65534 "$tmp/user"
elif [ "$(id -u)" -ne 0 ]; then
    mkdir "$tmp/user"
fi
if [ -d "$tmp/user" ]; then
    $as_user "$fs" run scenarios/static_load.ini $short --out "$tmp/user/ro" >/dev/null 2>&1
    cp "$tmp/user/ro/metrics.json" "$tmp/user.before" && chmod a-w "$tmp/user/ro"
    $as_user "$fs" run scenarios/static_load.ini $short --out "$tmp/user/ro" >/dev/null 2>"$tmp/user.err"
    su=$?
    check '[ "$su" -eq 4 ] && grep -q -- "--out .*user/ro: cannot be replaced: .*user/ro cannot be written (Permission denied); make it writable" "$tmp/user.err"'
    check 'cmp -s "$tmp/user.before" "$tmp/user/ro/metrics.json" && [ "$(ls -A "$tmp/user")" = ro ]'
    chmod u+w "$tmp/user/ro"
else
    echo "skipped: root without setpriv writes a chmod a-w folder (the read-only-folder case of issue 33 item 13)"
fi

# issue 33 item 14: a campaign journal that is a folder, or a symbolic link (not followed), is named
# as such (exit 2), not "the header ends early" or "Too many levels of symbolic links" (exit 4)
mkdir -p "$tmp/jf.journal/journal"
expect 2 "jf.journal/journal: is a folder, not a campaign journal.*--fresh" -- campaign scenarios/landing_ci.ini --set campaign.seeds=1 --out "$tmp/jf"
mkdir "$tmp/jl.journal" && echo "elsewhere" >"$tmp/elsewhere" && ln -s "$tmp/elsewhere" "$tmp/jl.journal/journal"
expect 2 "jl.journal/journal: is a symbolic link; footsim does not follow links for a campaign journal" -- campaign scenarios/landing_ci.ini --set campaign.seeds=1 --out "$tmp/jl"
check '[ "$(cat "$tmp/elsewhere")" = elsewhere ] && [ ! -e "$tmp/jf" ] && [ ! -e "$tmp/jl" ]'

# issue 33 item 14: gnuplot failing on a campaign's chart names the folder the data end up in, not
# the partial folder that is gone by then
. tests/small_campaign.sh
mkdir "$tmp/bin" && printf '#!/bin/sh\nexit 1\n' >"$tmp/bin/gnuplot" && chmod +x "$tmp/bin/gnuplot"
PATH="$tmp/bin:$PATH" camp -j 2 --out "$tmp/gp" >/dev/null 2>"$tmp/gp.err"
check 'grep -q "gnuplot failed: no chart $tmp/gp/success.png (the data and script chart.gp are in $tmp/gp)" "$tmp/gp.err" && ! grep -q partial "$tmp/gp.err" && [ -f "$tmp/gp/chart.gp" ]'

# the committed results folders carry the marker
for d in results/landing results/roughness results/baseline results/bench; do
    check "[ -f $d/.footsim-results ]"
done
finish
