#!/bin/sh
# footsim run --frames and render-compare write what they say: one PNG per frame at the asked size,
# a filmstrip, and without ffmpeg on the PATH a clear note instead of a video (exit 0); trial and
# walk --frames draw exactly their run; --exaggerate says so; the foot camera is the default;
# campaign --frames-of draws chosen trials and leaves every summary file byte-identical.
# Usage: cli_frames.sh path/to/footsim (run from the source folder, footsim built with the renderer).
fs=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0 failed=0

# check DESCRIPTION COMMAND...: the command succeeds; its output is then in $tmp/out
check() {
    what=$1
    shift
    if "$@" >"$tmp/cur" 2>"$tmp/err"; then
        passed=$((passed + 1))
    else
        failed=$((failed + 1))
        echo "FAIL: $what" >&2
        cat "$tmp/cur" "$tmp/err" >&2
    fi
    mv "$tmp/cur" "$tmp/out"
}

# The PNG's width and height, read from its IHDR chunk (bytes 17-24).
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{print $3 * 256 + $4 "x" $7 * 256 + $8}'; }

sl=scenarios/static_load.ini
check "run --frames" "$fs" run $sl --frames --size 64x48 --fps 100 --out "$tmp/run"
n=$(ls "$tmp/run/frames" | grep -c '^[0-9]\{6\}\.png$')
check "a frame per 1/100 s of the run and one at its end ($n frames)" [ "$n" -ge 20 ]
check "frames are 64x48" [ "$(png_size "$tmp/run/frames/000000.png")" = 64x48 ]
check "the run's results are written too" [ -s "$tmp/run/metrics.json" ]
# a second, shorter run leaves none of the first run's frames behind
check "run --frames again" "$fs" run $sl --frames --size 64x48 --fps 10 --out "$tmp/run"
check "old frames removed" [ "$(ls "$tmp/run/frames" | wc -l)" -lt "$n" ]
check "--video without ffmpeg" env PATH=/nonexistent "$fs" run $sl --frames --size 64x48 --video --out "$tmp/nov"
check "says ffmpeg is not installed" grep -q "ffmpeg is not installed" "$tmp/out"
check "no video" [ ! -e "$tmp/nov/video.mp4" ]
check "render-compare" "$fs" render-compare $sl $sl --set b:foot.kind=flat --size 128x48 --out "$tmp/cmp"
check "names both feet" grep -q "biomimetic foot, left.*flat foot, right" "$tmp/out"
check "compare frames are 128x48" [ "$(png_size "$tmp/cmp/frames/000000.png")" = 128x48 ]
check "filmstrip: 5 cells of 32x24 by 2 rows" [ "$(png_size "$tmp/cmp/filmstrip.png")" = 160x48 ]
# cells of 96 px and more get a legend band under the two rows (16 px up to 480 px)
check "render-compare, larger" "$fs" render-compare $sl $sl --set b:foot.kind=flat --size 400x200 --fps 20 --out "$tmp/cmp2"
check "the foot camera is the default" grep -q "camera foot" "$tmp/out"
check "filmstrip: 5 cells of 100x100 by 2 rows and a legend band" [ "$(png_size "$tmp/cmp2/filmstrip.png")" = 500x216 ]
# --exaggerate: said in the output and drawn differently from the true-size frames of the same run
check "run --frames --exaggerate 20" "$fs" run $sl --frames --size 160x90 --fps 10 --exaggerate 20 --out "$tmp/ex"
check "says the displacements are exaggerated" grep -q "displacements x20" "$tmp/out"
check "run --frames at true size" "$fs" run $sl --frames --size 160x90 --fps 10 --out "$tmp/true"
last=$(ls "$tmp/ex/frames" | tail -1)
check "the last exaggerated frame differs from the true-size one" sh -c "! cmp -s '$tmp/ex/frames/$last' '$tmp/true/frames/$last'"
expect_refused() { # expect_refused DESCRIPTION COMMAND...: exit 2; its stderr in $tmp/refused
    what=$1
    shift
    "$@" >"$tmp/cur" 2>"$tmp/refused"
    if [ $? -eq 2 ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL: $what" >&2; cat "$tmp/refused" >&2; fi
}
expect_refused "--exaggerate 0.5 refused" "$fs" run $sl --frames --exaggerate 0.5 --out "$tmp/ex2"
check "  and named" grep -q -- "--exaggerate 0.5: not a factor" "$tmp/refused"
# a landing trial looked at by its seed: its frames and its result, the same outcome as without frames
check "trial --frames" "$fs" trial scenarios/landing_trial.ini --seed 3 --frames --size 64x48 --fps 20 --out "$tmp/trial"
check "trial frames written" [ -s "$tmp/trial/frames/000000.png" ]
check "trial.json beside them" grep -q '"seed":[[:space:]]*3' "$tmp/trial/trial.json"
"$fs" trial scenarios/landing_trial.ini --seed 3 --json >"$tmp/plain.json"
check "the same outcome and rule as without frames" [ "$(grep -E '"(outcome|rule|end_time_s)"' "$tmp/plain.json")" = "$(grep -E '"(outcome|rule|end_time_s)"' "$tmp/trial/trial.json")" ]
# the walking machine, one step
check "walk --frames" "$fs" walk scenarios/walking.ini --set walk.steps=1 --frames --size 64x48 --fps 5 --out "$tmp/walk"
check "walk frames written" [ -s "$tmp/walk/frames/000000.png" ]
check "walk.json beside them" grep -q '"steps_completed"' "$tmp/walk/walk.json"
# campaign --frames-of: the chosen trial's frames, and the summaries byte for byte as without
cat >"$tmp/small.ini" <<EOF
[campaign]
trial = $PWD/scenarios/campaign_test_trial.ini
seeds = 2

[foot.bio]
file = $PWD/scenarios/feet/biomimetic.ini

[terrain.flat]
file = $PWD/terrains/flat.ini
EOF
check "campaign" "$fs" campaign "$tmp/small.ini" -j 2 --set run.duration_s=0.3 --out "$tmp/camp1"
check "campaign --frames-of" "$fs" campaign "$tmp/small.ini" -j 2 --set run.duration_s=0.3 --out "$tmp/camp2" --frames-of foot=bio,seed=2 --size 64x48 --fps 10
cp "$tmp/err" "$tmp/camp2.err"
check "which trial it draws, said" grep -q -- '--frames-of: drawing 1 of 1: bio on flat under drop_weight, seed 2' "$tmp/camp2.err"
check "the chosen trial's frames" [ -s "$tmp/camp2/frames/bio-flat-drop_weight-seed2/000000.png" ]
check "no other trial's" [ "$(ls "$tmp/camp2/frames")" = bio-flat-drop_weight-seed2 ]
for f in summary.md summary.csv summary.json trials.csv chart.dat; do
    check "$f byte-identical with --frames-of" cmp "$tmp/camp1/$f" "$tmp/camp2/$f"
done
expect_refused "--frames-of with an unknown foot refused" "$fs" campaign "$tmp/small.ini" --out "$tmp/camp3" --frames-of foot=nope
check "  naming the feet there are" grep -q "foot 'nope' is not in this campaign; allowed: bio" "$tmp/refused"
check "  before anything is written" [ ! -e "$tmp/camp3" ]
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
