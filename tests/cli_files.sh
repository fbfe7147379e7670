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
expect 2 "2200000 trials; a campaign may run at most 1000000" -- campaign scenarios/roughness.ini \
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
finish
