#!/bin/sh
# The footsim command refuses bad input with "file:line: ..." on stderr and exit status 2, and
# writes nothing. Usage: cli_bad_input.sh path/to/footsim [render|norender] (run from the source
# folder; the second argument says whether footsim was built with the renderer).
fs=$1
renderer=${2:-render}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0 failed=0

# expect STATUS PATTERN -- ARGS...: exit status and a pattern that stderr must contain
expect() {
    want=$1 pattern=$2
    shift 3
    "$fs" "$@" >"$tmp/out" 2>"$tmp/err"
    got=$?
    if [ "$got" -eq "$want" ] && grep -q -- "$pattern" "$tmp/err"; then
        passed=$((passed + 1))
    else
        failed=$((failed + 1))
        echo "FAIL: footsim $* gave status $got (wanted $want); stderr:" >&2
        cat "$tmp/err" >&2
        echo "  (wanted it to contain: $pattern)" >&2
    fi
}

printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[load]\nmass_kg = -26\n' "$PWD" >"$tmp/neg.ini"
printf '[scenario]\ndesign = nowhere.ini\n' >"$tmp/nodesign.ini"
printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[run]\nstep_s = 1e-4\nstep_s = 1e-3\n' "$PWD" >"$tmp/dup.ini"

expect 2 "$tmp/neg.ini:4: mass_kg = '-26' is out of range" -- run "$tmp/neg.ini" --out "$tmp/o1"
expect 2 "$tmp/nodesign.ini:2: design = 'nowhere.ini': no such file" -- run "$tmp/nodesign.ini" --out "$tmp/o2"
expect 2 "$tmp/dup.ini:5: \[run\] step_s is given twice" -- run "$tmp/dup.ini" --out "$tmp/o3"
expect 2 "missing.ini: No such file" -- run missing.ini --out "$tmp/o4"
expect 2 "--set springs.k_d2_N_per_m: k_d2_N_per_m = '0' is out of range" -- run scenarios/static_load.ini --set springs.k_d2_N_per_m=0 --out "$tmp/o5"
expect 2 "unknown option --frobnicate" -- run scenarios/static_load.ini --frobnicate
expect 2 "give a SCENARIO file" -- run
expect 2 "unknown command" -- sprint
expect 2 "cannot create folder" -- run scenarios/static_load.ini --out /proc/footsim/out
expect 2 "unknown section \[wheels\]" -- stiffness scenarios/feet/biomimetic.ini --set wheels.count=4

# frame options: refused before the simulation starts
sl=scenarios/static_load.ini
if [ "$renderer" = render ]; then
    mkdir -p "$tmp/f6" && : >"$tmp/f6/frames"
    expect 2 "--size 0x10: not a frame size; allowed: WxH" -- run $sl --frames --size 0x10 --out "$tmp/f1"
    expect 2 "--size 9000x10: not a frame size; allowed: WxH with W from 1 and H from 1, each to 8192" -- run $sl --frames --size 9000x10 --out "$tmp/f1"
    expect 2 "--size 640: not a frame size" -- run $sl --frames --size 640 --out "$tmp/f1"
    expect 2 "--camera top: unknown camera; allowed: side, front, three-quarter, follow" -- run $sl --frames --camera top --out "$tmp/f2"
    expect 2 "--fps 0: not a frame rate; allowed: frames per simulated second from 1 to 10000" -- run $sl --frames --fps 0 --out "$tmp/f3"
    expect 2 "--fps abc: not a frame rate" -- run $sl --frames --fps abc --out "$tmp/f3"
    expect 2 "--fps 20000: not a frame rate" -- run $sl --frames --fps 20000 --out "$tmp/f3"
    expect 2 "--fps 2000: not a frame rate.*one frame per step of 0.001 s" -- run $sl --frames --fps 2000 --set run.step_s=1e-3 --out "$tmp/f4"
    expect 2 "frames: not a folder" -- run $sl --frames --out "$tmp/f6"
    expect 2 "cannot create folder" -- run $sl --frames --out /proc/footsim/frames
    expect 2 "give two scenario files" -- render-compare $sl --out "$tmp/f5"
    expect 2 "--size 1x10: not a frame size; allowed: WxH with W from 2" -- render-compare $sl $sl --size 1x10 --out "$tmp/f5"
    expect 2 "unexpected argument" -- render-compare $sl $sl $sl
    # no OSMesa to load (FOOTSIM_OSMESA names the library in its place)
    export FOOTSIM_OSMESA="$tmp/no/libOSMesa.so.8"
    expect 2 "OSMesa is not available.*apt-get install libosmesa6" -- run $sl --frames --out "$tmp/f1"
    expect 2 "OSMesa is not available" -- render-compare $sl $sl --out "$tmp/f5"
    unset FOOTSIM_OSMESA
else
    expect 2 "--frames: this footsim was built without the renderer" -- run $sl --frames --out "$tmp/f1"
    expect 2 "render-compare: this footsim was built without the renderer" -- render-compare $sl $sl --out "$tmp/f5"
fi

# nothing was written for any refused run (a frame-option run may leave its empty folder)
for d in o1 o2 o3 o4 o5; do
    if [ -e "$tmp/$d" ]; then failed=$((failed + 1)); echo "FAIL: $tmp/$d was created" >&2; else passed=$((passed + 1)); fi
done
for d in f1 f2 f3 f4 f5; do
    if [ -n "$(find "$tmp/$d" -type f 2>/dev/null)" ]; then
        failed=$((failed + 1)); echo "FAIL: files were written in $tmp/$d" >&2
    else
        passed=$((passed + 1))
    fi
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
