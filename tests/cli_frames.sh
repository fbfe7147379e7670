#!/bin/sh
# footsim run --frames and render-compare write what they say: one PNG per frame at the asked size,
# a filmstrip, and without ffmpeg on the PATH a clear note instead of a video (exit 0).
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
# a landing trial looked at by its seed: its frames and its result, the same outcome as without frames
check "trial --frames" "$fs" trial scenarios/landing_trial.ini --seed 3 --frames --size 64x48 --fps 20 --out "$tmp/trial"
check "trial frames written" [ -s "$tmp/trial/frames/000000.png" ]
check "trial.json beside them" grep -q '"seed":[[:space:]]*3' "$tmp/trial/trial.json"
"$fs" trial scenarios/landing_trial.ini --seed 3 --json >"$tmp/plain.json"
check "the same outcome and rule as without frames" [ "$(grep -E '"(outcome|rule|end_time_s)"' "$tmp/plain.json")" = "$(grep -E '"(outcome|rule|end_time_s)"' "$tmp/trial/trial.json")" ]
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
