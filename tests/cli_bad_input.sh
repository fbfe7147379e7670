#!/bin/sh
# The footsim command refuses bad input with "file:line: ..." on stderr and exit status 2, and
# writes nothing. Usage: cli_bad_input.sh path/to/footsim [render|norender] (run from the source
# folder; the second argument says whether footsim was built with the renderer).
renderer=${2:-render}
. "$(dirname "$0")/cli_check.sh"

printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[load]\nmass_kg = -26\n' "$PWD" >"$tmp/neg.ini"
printf '[scenario]\ndesign = nowhere.ini\n' >"$tmp/nodesign.ini"
printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[run]\nstep_s = 1e-4\nstep_s = 1e-3\n' "$PWD" >"$tmp/dup.ini"

expect 2 "$tmp/neg.ini:4: mass_kg = '-26' is out of range" -- run "$tmp/neg.ini" --out "$tmp/o1"
expect 2 "$tmp/nodesign.ini:2: design = 'nowhere.ini': no such file" -- run "$tmp/nodesign.ini" --out "$tmp/o2"
expect 2 "$tmp/dup.ini:5: \[run\] step_s is given twice" -- run "$tmp/dup.ini" --out "$tmp/o3"
expect 2 "missing.ini: cannot open an .ini file (No such file or directory)" -- run missing.ini --out "$tmp/o4"
expect 2 "--set springs.k_d2_N_per_m: k_d2_N_per_m = '0' is out of range" -- run scenarios/static_load.ini --set springs.k_d2_N_per_m=0 --out "$tmp/o5"
expect 2 "unknown option --frobnicate" -- run scenarios/static_load.ini --frobnicate
expect 2 "give a SCENARIO file" -- run
expect 2 "unknown command" -- sprint
expect 2 "cannot create folder" -- run scenarios/static_load.ini --out /proc/footsim/out
expect 2 "unknown section \[wheels\]" -- stiffness scenarios/feet/biomimetic.ini --set wheels.count=4
# a list's element is counted from 1: [0] and past the end refused with the valid range
expect 2 "--set chains.splay_deg\[0\]: splay_deg\[0\]: no such element; give one of splay_deg\[1\] to splay_deg\[5\]" -- \
    stiffness scenarios/feet/biomimetic.ini --set 'chains.splay_deg[0]=0'
# --data must be a folder; a relative path not found as given is looked for there (and in its
# scenarios/feet/ for a design), and paths inside the file stay relative to the file
expect 2 "--data $tmp/none: not a folder" -- run static_load.ini --data "$tmp/none"
src=$PWD
check '(cd "$tmp" && "$fs" model biomimetic.ini --data "$src" | grep -q "^$src/scenarios/feet/biomimetic.ini: biomimetic foot")'
check '(cd "$tmp" && "$fs" terrain heightmap.ini --data "$src" | grep -q "^$src/terrains/heightmap.ini: heightmap terrain")'

# robots: their keys live in robot files (scenarios/robots/), checked like any other file
printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[robot]\nmass_kg = 26\n' "$PWD" >"$tmp/inline.ini"
printf '[robot]\nmass_kg = 26\nmount = sideways\n' >"$tmp/bad_robot.ini"
printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[robot]\ndesign = bad_robot.ini\n' "$PWD" >"$tmp/uses_bad.ini"
expect 2 "$tmp/inline.ini:4: 'mass_kg' is a key of a robot file, not of a scenario" -- trial "$tmp/inline.ini"
expect 2 "$tmp/bad_robot.ini:3: mount = 'sideways'" -- trial "$tmp/uses_bad.ini"
expect 2 "--set robot.mass: unknown key 'mass' in \[robot\]" -- trial scenarios/landing_trial.ini --set robot.mass=3
# a biped's mass follows from its parts; a single body has no legs; the walking machine carries no biped
printf '[robot]\nkind = biped\nmass_kg = 52\n' >"$tmp/heavy_biped.ini"
printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[robot]\ndesign = heavy_biped.ini\n' "$PWD" >"$tmp/uses_heavy.ini"
expect 2 "$tmp/heavy_biped.ini:3: 'mass_kg' is a single body's key and this robot is a biped" -- trial "$tmp/uses_heavy.ini"
expect 2 "--set robot.hip_width_m: 'hip_width_m' is a biped's key and this robot is one body" -- trial scenarios/landing_trial.ini --set robot.hip_width_m=0.3
expect 2 "--set robot.design: .*robots/biped.ini is a biped, and the walking machine carries one body" -- walk scenarios/walking.ini --set robot.design=robots/biped.ini
# spring laws (docs/model.md): a key of another law, a curve that does not rise; a law MuJoCo cannot take
expect 2 "--set springs.d1_x0_m: d1_x0_m is a key of the progressive law, but d1_law is linear" -- run scenarios/static_load.ini --set springs.d1_x0_m=0.002 --out "$tmp/o6"
expect 2 "--set springs.d3_curve_N: d3_curve_N is not increasing" -- run scenarios/static_load.ini --set springs.d3_law=curve --set "springs.d3_curve_m=0, 0.001" --set "springs.d3_curve_N=0, -1" --out "$tmp/o7"
# (named at the line of that spring's law key, or its --set, as every refusal; with --scenario too)
law_line=$(grep -n '^d1_law' scenarios/feet/progressive_cable.ini | cut -d: -f1)
expect 2 "scenarios/feet/progressive_cable.ini:$law_line: spring d1_chain1's law is progressive, which MuJoCo 2.2.2's tendons cannot express" -- export scenarios/feet/progressive_cable.ini --mjcf --out "$tmp/prog.xml"
printf '[springs]\nd2_law = bilinear\nd2_stop_m = 0.001\nd2_k2_N_per_m = 50000\n' >"$tmp/bilinear.ini"
expect 2 "$tmp/bilinear.ini:2: spring d2_chain1's law is bilinear" -- export "$tmp/bilinear.ini" --mjcf --scenario scenarios/landing_trial.ini --out "$tmp/bilinear.xml"
expect 2 "--set springs.d3_law: spring d3_chain1's law is progressive" -- export scenarios/feet/biomimetic.ini --mjcf --set springs.d3_law=progressive --out "$tmp/prog3.xml"
expect 2 "scenarios/robots/biped.ini: kind = biped: the biped is not exported" -- export scenarios/feet/biomimetic.ini --mjcf --scenario scenarios/landing_trial.ini --set robot.design=robots/biped.ini --out "$tmp/biped.xml"
# moments of inertia no body has (one above the other two together): refused where they are given
expect 2 "--set robot.inertia_kgm2: inertia_kgm2 = 0.01, 0.01, 1 is no rigid body's: the moment about z (1 kg m^2) is more than those about x and y together (0.02).*give the moment about z at most 0.02" -- trial scenarios/landing_trial.ini --set robot.inertia_kgm2=0.01,0.01,1
printf '[robot]\nmass_kg = 26\ninertia_kgm2 = 0.1, 0.5, 0.3\n' >"$tmp/rod_robot.ini"
printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[robot]\ndesign = rod_robot.ini\n' "$PWD" >"$tmp/uses_rod.ini"
expect 2 "$tmp/rod_robot.ini:3: inertia_kgm2 = 0.1, 0.5, 0.3 is no rigid body's: the moment about y" -- trial "$tmp/uses_rod.ini"
expect 2 "--set robot.pelvis_inertia_kgm2: pelvis_inertia_kgm2 = 1, 0.2, 0.2 is no rigid body's" -- trial scenarios/landing_trial.ini --set robot.design=robots/biped.ini --set robot.pelvis_inertia_kgm2=1,0.2,0.2
printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[landing]\nlanded_tilt_deg = 15\n' "$PWD" >"$tmp/norobot.ini"
expect 2 "$tmp/norobot.ini: a landing trial drops a robot and this scenario has none" -- trial "$tmp/norobot.ini"

# campaigns: refused with file:line before any trial runs (nothing written)
camp() { # camp NAME BODY: a campaign file on the stand-in trial with one foot and one terrain
    printf '[campaign]\ntrial = %s/scenarios/campaign_test_trial.ini\n%b\n[foot.bio]\nfile = %s/scenarios/feet/biomimetic.ini\n[terrain.flat]\nfile = %s/terrains/flat.ini\n' \
        "$PWD" "$2" "$PWD" "$PWD" >"$tmp/$1.ini"
}
camp zero 'seeds = 0'
camp unknown 'seeds = 3\nspeed = 2'
camp range 'seeds = 3\n[expect.e]\nfoot = bio\nterrain = flat\nmin_success = 1.5'
camp nofoot 'seeds = 3\n[foot.ghost]\nfile = feet/ghost.ini'
camp noterrain 'seeds = 3\n[expect.e]\nfoot = bio\nterrain = rocks'
camp minmax 'seeds = 3\n[expect.e]\nfoot = bio\nterrain = flat\nmin_success = 0.8\nmax_success = 0.5'
camp sweep 'seeds = 3\nsweep = rough.rms_m\nsweep_values = 0, 0.001, abc'
camp nosweep 'seeds = 3\nsweep_values = 0, 0.001'
expect 2 "$tmp/zero.ini:3: seeds = '0' is out of range; allowed: a whole number in \[1, 100000\]" -- campaign "$tmp/zero.ini" --out "$tmp/c1"
expect 2 "$tmp/unknown.ini:4: unknown key 'speed' in \[campaign\]" -- campaign "$tmp/unknown.ini" --out "$tmp/c2"
expect 2 "$tmp/range.ini:7: min_success = '1.5' is out of range" -- campaign "$tmp/range.ini" --out "$tmp/c3"
expect 2 "$tmp/nofoot.ini:5: file = 'feet/ghost.ini': no such file" -- campaign "$tmp/nofoot.ini" --out "$tmp/c4"
expect 2 "$tmp/noterrain.ini:6: terrain = 'rocks' is not one of the choices; allowed: flat" -- campaign "$tmp/noterrain.ini" --out "$tmp/c5"
expect 2 "$tmp/minmax.ini:7: min_success = 0.8 is above max_success = 0.5" -- campaign "$tmp/minmax.ini" --out "$tmp/c6"
expect 2 "$tmp/sweep.ini:5: sweep_values: 'abc' is not a finite number" -- campaign "$tmp/sweep.ini" --out "$tmp/c7"
expect 2 "$tmp/nosweep.ini:4: sweep_values without sweep" -- campaign "$tmp/nosweep.ini" --out "$tmp/c8"
# a robot's own error-controlled step: an estimate without a tolerance is refused at its line; a
# tolerance the trial cannot take names the robot's section that gave it
camp estimate "seeds = 3\n[robot.r]\nfile = $PWD/scenarios/robots/drop_weight.ini\nerror_estimate = embedded"
camp tolerant "seeds = 3\n[robot.r]\nfile = $PWD/scenarios/robots/drop_weight.ini\ntolerance_m = 1e-6"
expect 2 "$tmp/estimate.ini:6: error_estimate is the error-controlled step's and this robot has no tolerance_m; give tolerance_m too" -- campaign "$tmp/estimate.ini" --out "$tmp/c8e"
expect 2 "tolerance_m = 1e-06 cannot be used here: ODE's auto-disable.*under robot r; \[robot.r\] gives its trials its step_s, tolerance_m or error_estimate as --set run" -- campaign "$tmp/tolerant.ini" --set run.auto_disable_s=0.1 --out "$tmp/c8t"
# a value given twice (equal as numbers) would make two points of one name; an empty value (two
# commas, a comma first or last) is a slip, refused in every list (a sweep's, a list key's)
camp twice 'seeds = 3\nsweep = rough.rms_m\nsweep_values = 0, 0.001, 0.001'
camp twice_e 'seeds = 3\nsweep = rough.rms_m\nsweep_values = 0.001, 1e-3, 0.00100'
camp twice2 'seeds = 3\nsweep = rough.rms_m\nsweep_values = 0, 0.001\nsweep2 = robot.com_height_m\nsweep2_values = 0.3, 0.2, 3e-1'
camp commas 'seeds = 3\nsweep = rough.rms_m\nsweep_values = 0,,0.001'
camp trailing 'seeds = 3\nsweep = rough.rms_m\nsweep_values = 0, 0.001,'
camp leading 'seeds = 3\nsweep = rough.rms_m\nsweep_values = , 0, 0.001'
expect 2 "$tmp/twice.ini:5: sweep_values: '0.001' is '0.001' again.*give each value once" -- campaign "$tmp/twice.ini" --out "$tmp/c10"
expect 2 "$tmp/twice_e.ini:5: sweep_values: '1e-3' is '0.001' again" -- campaign "$tmp/twice_e.ini" --out "$tmp/c10"
expect 2 "$tmp/twice2.ini:7: sweep2_values: '3e-1' is '0.3' again" -- campaign "$tmp/twice2.ini" --out "$tmp/c10"
expect 2 "$tmp/commas.ini:5: sweep_values: value 2 is empty" -- campaign "$tmp/commas.ini" --out "$tmp/c10"
expect 2 "$tmp/trailing.ini:5: sweep_values: value 3 is empty" -- campaign "$tmp/trailing.ini" --out "$tmp/c10"
expect 2 "$tmp/leading.ini:5: sweep_values: value 1 is empty" -- campaign "$tmp/leading.ini" --out "$tmp/c10"
expect 2 "--set campaign.sweep_values: sweep_values: '1.0' is '1' again" -- campaign scenarios/envelope.ini --set campaign.sweep_values=1,1.0 --out "$tmp/c10"
check '[ ! -e "$tmp/c10" ]'
printf '[robot]\nmass_kg = 26\ninertia_kgm2 = 1.4,,1.4, 0.1\n' >"$tmp/commas_robot.ini"
printf '[robot]\nmass_kg = 26\ninertia_kgm2 = 1.4, 1.4, 0.1,\n' >"$tmp/trailing_robot.ini"
printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[robot]\ndesign = %s\n' "$PWD" commas_robot.ini >"$tmp/uses_commas.ini"
printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[robot]\ndesign = %s\n' "$PWD" trailing_robot.ini >"$tmp/uses_trailing.ini"
expect 2 "$tmp/commas_robot.ini:3: inertia_kgm2 = '1.4,,1.4, 0.1' has an empty value (value 2" -- trial "$tmp/uses_commas.ini"
expect 2 "$tmp/trailing_robot.ini:3: inertia_kgm2 = '1.4, 1.4, 0.1,' has an empty value (value 4" -- trial "$tmp/uses_trailing.ini"
expect 2 "--set mud.depth: unknown section \[mud\].*(campaign scenarios/landing_ci.ini: foot biomimetic on terrain flat under robot single_tall)" -- campaign scenarios/landing_ci.ini --set mud.depth=3 --out "$tmp/c9"
expect 2 "no such file" -- campaign scenarios/landing_ci.ini --set terrain.flat.file=../terrains/lava.ini --out "$tmp/c9"
expect 2 "\-j 0: not a number of workers; allowed: a whole number from 1 to 1024" -- campaign scenarios/landing_ci.ini -j 0 --out "$tmp/c9"
expect 2 "give two summary.json files" -- compare results/baseline/landing.json

# frame options: refused before the simulation starts
sl=scenarios/static_load.ini
if [ "$renderer" = render ]; then
    expect 2 "--size 0x10: not a frame size; allowed: WxH" -- run $sl --frames --size 0x10 --out "$tmp/f1"
    expect 2 "--size 9000x10: not a frame size; allowed: WxH with W from 1 and H from 1, each to 8192" -- run $sl --frames --size 9000x10 --out "$tmp/f1"
    expect 2 "--size 640: not a frame size" -- run $sl --frames --size 640 --out "$tmp/f1"
    expect 2 "--camera top: unknown camera; allowed: foot, side, front, three-quarter, follow" -- run $sl --frames --camera top --out "$tmp/f2"
    expect 2 "--fps 0: not a frame rate; allowed: frames per simulated second from 1 to 10000" -- run $sl --frames --fps 0 --out "$tmp/f3"
    expect 2 "--fps abc: not a frame rate" -- run $sl --frames --fps abc --out "$tmp/f3"
    expect 2 "--fps 20000: not a frame rate" -- run $sl --frames --fps 20000 --out "$tmp/f3"
    expect 2 "--fps 2000: not a frame rate.*one frame per step of 0.001 s" -- run $sl --frames --fps 2000 --set run.step_s=1e-3 --out "$tmp/f4"
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
for d in o1 o2 o3 o4 o5 c1 c2 c3 c4 c5 c6 c7 c8 c9; do
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
