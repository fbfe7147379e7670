#!/bin/sh
# Issue 16: hostile input files through the command. Each case is a finding's reproducer; each must
# be refused with exit 2 and file:line before anything is simulated or written.
# Usage: cli_files.sh path/to/footsim [render|norender] (run from the source folder).
renderer=${2:-render}
. "$(dirname "$0")/cli_check.sh"
src=$PWD
# scenario NAME DESIGN_FILE [extra lines]: a static-load scenario on that design
scenario() {
    printf '[scenario]\ndesign = %s\nterrain = %s/terrains/flat.ini\n[run]\nduration_s = 0.02\n%b' "$2" "$src" "${3:-}" >"$tmp/s_$1.ini"
}

# ---- finding 2: files silently misread -----------------------------------------------------------
printf '[links]\rl1_m = 0.03\r' >"$tmp/cr.ini"
scenario cr "$tmp/cr.ini"
expect 2 "$tmp/cr.ini:1: a carriage return that does not end a line" -- run "$tmp/s_cr.ini" --out "$tmp/o"
printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[load] mass_kg = 5\n' "$src" >"$tmp/after.ini"
expect 2 "$tmp/after.ini:3: text after ']'" -- run "$tmp/after.ini" --out "$tmp/o"
printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[load]\ntilt_deg = 5\0garbage\n' "$src" >"$tmp/nul.ini"
expect 2 "$tmp/nul.ini:4: a NUL byte" -- run "$tmp/nul.ini" --out "$tmp/o"
{ printf '[foot]\nkind = biomimetic\0'; head -c 300 /dev/zero | tr '\0' x; printf 'kind = flat\n'; } >"$tmp/hidden.ini"
scenario hidden "$tmp/hidden.ini"
expect 2 "$tmp/hidden.ini:2: a NUL byte" -- run "$tmp/s_hidden.ini" --out "$tmp/o"
head -c 100 /dev/zero >"$tmp/nuls.ini"
expect 2 "$tmp/nuls.ini:1: a NUL byte" -- model "$tmp/nuls.ini"
: >"$tmp/empty.ini"
printf ' \n\t\n' >"$tmp/blank.ini"
printf '\357\273\277' >"$tmp/bom.ini"
for f in empty blank bom; do
    expect 2 "$tmp/$f.ini:1: no keys" -- model "$tmp/$f.ini"
    expect 2 "$tmp/$f.ini:1: no keys" -- terrain "$tmp/$f.ini"
done
printf '[links]\nl1_m = 0.02\n[unknown_section]\n' >"$tmp/unknown.ini"
expect 2 "$tmp/unknown.ini:3: \[unknown_section\] has no keys" -- model "$tmp/unknown.ini"
# a NUL that hid an over-long line injected "seeds = 2" into a campaign
{ printf '[campaign]\ntrial = %s/scenarios/landing_trial.ini\nseeds = 1 ;\0' "$src"; head -c 300 /dev/zero | tr '\0' x
  printf 'seeds = 2\n[foot.flat]\nfile = %s/scenarios/feet/flat.ini\n[terrain.flat]\nfile = %s/terrains/flat.ini\n' "$src" "$src"; } >"$tmp/camp.ini"
expect 2 "$tmp/camp.ini:3: a NUL byte" -- campaign "$tmp/camp.ini" --out "$tmp/c"

# ---- finding 6: sizes bounded up front (steps, trajectory rows, trials, frames) ---------------------
sl=scenarios/static_load.ini
expect 2 "run.duration_s: duration_s / step_s = 4.295e+09 steps; a run may take at most 1e+09" -- run $sl \
    --set run.step_s=1e-5 --set run.log_interval_s=1e-5 --set run.duration_s=42949.67794 --out "$tmp/o"
expect 2 "trajectory rows .* at most 1.07 GB" -- run $sl --set run.step_s=1e-5 --set run.log_interval_s=1e-5 \
    --set run.duration_s=1000 --out "$tmp/o"
expect 2 "x 100000 seeds = 4400000 trials; a campaign may run at most 1000000" -- campaign scenarios/roughness.ini \
    --set campaign.seeds=100000 --out "$tmp/c"
expect 2 "at most 1e+09" -- walk scenarios/walking.ini --set walk.steps=1000 --set walk.period_s=100 --set run.step_s=1e-7
if [ "$renderer" = render ]; then
    expect 2 "more than 999999 frames" -- run $sl --frames --fps 10000 --set run.duration_s=100 --out "$tmp/o"
    expect 2 "too many frames to keep" -- render-compare $sl $sl --fps 10000 --set run.duration_s=100 --out "$tmp/o"
fi
check '[ ! -e "$tmp/o" ] && [ ! -e "$tmp/c" ] && [ -z "$(ls -a "$tmp" | grep -e "partial" -e "lock")" ]'

# ---- finding 9: only regular files of bounded size are read (a FIFO blocked, /dev/zero filled memory) --
mkfifo "$tmp/fifo.json"
real_fs=$fs fs="$tmp/footsim_timeout" # a hang ends after 20 s (status 124) instead of stalling the suite
printf '#!/bin/sh\nexec timeout 20 "%s" "$@"\n' "$real_fs" >"$fs" && chmod +x "$fs"
expect 2 "fifo.json: is a FIFO; give a summary.json" -- compare "$tmp/fifo.json" results/baseline/landing.json
expect 2 "/dev/zero: is a character device" -- compare /dev/zero results/baseline/landing.json
expect 2 "fifo.json: is a FIFO; give an .ini file" -- model "$tmp/fifo.json"
fs=$real_fs

# ---- finding 7: every command-line coordinate range-checked (1e308 overflowed a lattice index) ------
expect 2 "--height X: 1e308 m is out of range; allowed: metres from -1000 to 1000" -- terrain terrains/rough.ini --height 1e308 1e308
expect 2 "--height Y: 'nan' is not a finite number" -- terrain terrains/rough.ini --height 0 nan

# ---- finding 11: messages that say the real reason -----------------------------------------------
mkdir "$tmp/adir"
ln -s "$tmp/loop1" "$tmp/loop2" && ln -s "$tmp/loop2" "$tmp/loop1"
expect 2 "adir: is a folder; give an .ini file" -- model "$tmp/adir"
expect 2 "/dev/null: is a character device" -- model /dev/null
expect 2 "loop1: cannot open an .ini file (Too many levels of symbolic links)" -- model "$tmp/loop1"
printf '[scenario]\ndesign = adir\n' >"$tmp/dirdesign.ini"
expect 2 "dirdesign.ini:2: design = 'adir': .*adir is a folder, not a file" -- run "$tmp/dirdesign.ini" --out "$tmp/o"
printf '[scenario]\ndesign = loop1\n' >"$tmp/loopdesign.ini"
expect 2 "loopdesign.ini:2: design = 'loop1': Too many levels of symbolic links" -- run "$tmp/loopdesign.ini" --out "$tmp/o"
if [ "$(id -u)" -ne 0 ]; then
    mkdir -p "$tmp/locked/in" && cp scenarios/feet/flat.ini "$tmp/locked/in/" && chmod 000 "$tmp/locked"
    expect 2 "Permission denied" -- model "$tmp/locked/in/flat.ini"
    chmod 755 "$tmp/locked"
else
    echo "skipped: running as root, a folder cannot be made unsearchable (the permission case of finding 11)"
fi
expect 2 "l1_m = '1e-308' is below the smallest normal double (2.2e-308)" -- model scenarios/feet/biomimetic.ini --set links.l1_m=1e-308
expect 2 "footsim: --set links.l3_m: chain 1's toe cannot rest .* from --set links.l3_m)" -- model scenarios/feet/biomimetic.ini --set links.l3_m=1e-300
check '! grep -q "biomimetic.ini:[0-9]" "$tmp/err"'
check '! grep -q "[0-9]\{30\}" "$tmp/err"' # no 300-digit number for tiny geometry

# ---- finding 12: nonsense refused ----------------------------------------------------------------
"$fs" run $sl --set load.mass_kg=-0 --set run.duration_s=0.02 --out "$tmp/zero" >"$tmp/zero.txt" 2>&1
check 'grep -q " 0.0 kg" "$tmp/zero.txt" && ! grep -q -- "-0.0 kg" "$tmp/zero.txt"'
expect 2 "mass_kg = '0x1P-1074' is hexadecimal; write it in decimal" -- run $sl --set load.mass_kg=0x1P-1074 --out "$tmp/o"
expect 2 "mass_kg = '4.9e-324' is below the smallest normal double" -- run $sl --set load.mass_kg=4.9e-324 --out "$tmp/o"
printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\nterrain = %s/terrains/heightmap.ini\n' "$src" "$src" >"$tmp/hm.ini"
expect 2 "heightmap.ini: the heightmap covers x 100\.\.[0-9.]* m.*the foot .* is off it" -- run "$tmp/hm.ini" --set heightmap.x0_m=100 --out "$tmp/o"
# a heightmap that covers only part of the foot's region runs, warned with where it was placed
expect 0 "warning: .*heightmap.ini: the heightmap covers x 0\.05\.\..*x0_m from --set heightmap.x0_m, y0_m from .*heightmap.ini:10).* [0-9][0-9]* % of the foot's region .* is outside it" -- run "$tmp/hm.ini" --set heightmap.x0_m=0.05 --set run.duration_s=0.01 --out "$tmp/hmpart"
"$fs" run "$tmp/hm.ini" --set run.duration_s=0.01 --out "$tmp/hmall" >/dev/null 2>"$tmp/hmall.err"
check '! grep -q warning "$tmp/hmall.err"'
expect 2 "period_s = 5e-05 gives a stance of 3e-05 s and a swing of 2e-05 s, one shorter than step_s = 0.0001" -- walk scenarios/walking.ini --set walk.period_s=5e-5

# ---- finding 13: options that contradicted each other without need --------------------------------
"$fs" run $sl --set run.step_s=1e-2 --set run.duration_s=0.05 --out "$tmp/coarse" >/dev/null 2>"$tmp/coarse.err"
s13=$?
# an unset log interval follows the step: rows 0.01 s apart
check '[ "$s13" -eq 0 ] && [ "$(sed -n 3p "$tmp/coarse/trajectory.csv" | cut -d, -f1)" = "0.01" ]'
expect 2 "--set run.log_interval_s: log_interval_s = 0.001 is shorter than step_s = 0.01 (from --set run.step_s)" -- run $sl --set run.step_s=1e-2 --set run.log_interval_s=1e-3 --out "$tmp/o"
# finding 11: a value from --set is named as such, not blamed on a line of the file
printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[run]\nlog_interval_s = 1e-3\n' "$src" >"$tmp/li.ini"
expect 2 "li.ini:4: log_interval_s = 0.001 is shorter than step_s = 0.01 (from --set run.step_s)" -- run "$tmp/li.ini" --set run.step_s=1e-2 --out "$tmp/o"
"$fs" run $sl --set run.duration_s=0.02 --fps 30 --out "$tmp/fps" >/dev/null 2>"$tmp/fps.err"
check 'grep -q "warning: --fps is unused without --frames" "$tmp/fps.err" && [ -f "$tmp/fps/metrics.json" ]'
expect 2 "--out given twice" -- run $sl --out "$tmp/o" --out "$tmp/o2"
printf '[scenario]\ndesign = %s/scenarios/feet/biomimetic.ini\n[run]\nduration_s = 0x10\n' "$src" >"$tmp/hex.ini"
expect 2 "hex.ini:4: duration_s = '0x10' is hexadecimal" -- run "$tmp/hex.ini" --out "$tmp/o"

# ---- finding 14: trial and run refuse the wrong kind of scenario, naming the right command ---------
expect 2 "static_load.ini: is a run scenario .* use \`footsim run" -- trial $sl
expect 2 "walking.ini: is a walking-machine scenario .* use \`footsim walk" -- run scenarios/walking.ini --out "$tmp/o"
expect 2 "use \`footsim run" -- walk $sl
check '[ ! -e "$tmp/o" ] && [ ! -e "$tmp/o2" ]'
finish
