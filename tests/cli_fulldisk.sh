#!/bin/sh
# Issue 16, findings 4 and 11: on a nearly full disk (a 2 MiB tmpfs mounted here), a chart gnuplot
# could write only in part is not installed, a PNG footsim writes itself fails the same way, and
# both say "No space left on device" with exit 4, the earlier results left whole. Skips, saying so,
# where the machine does not allow mounting. Usage: cli_fulldisk.sh path/to/footsim.
. "$(dirname "$0")/cli_check.sh"
src=$PWD
disk="$tmp/disk"
mkdir "$disk"
if ! mount -t tmpfs -o size=2m tmpfs "$disk" 2>/dev/null; then
    echo "skipped: cannot mount a small tmpfs here (needs root and mount rights): the full-disk cases of findings 4 and 11"
    finish
    exit $?
fi
trap 'umount "$disk"; rm -rf "$tmp"' EXIT
# fill DISK leaving BYTES free
leave() { rm -f "$disk/fill"; avail=$(df -B1 --output=avail "$disk" | tail -1); fallocate -l $((avail - $1)) "$disk/fill"; }
printf '[campaign]\ntrial = %s/scenarios/campaign_test_trial.ini\nseeds = 2\n[foot.bio]\nfile = %s/scenarios/feet/biomimetic.ini\n[terrain.flat]\nfile = %s/terrains/flat.ini\n' \
    "$src" "$src" "$src" >"$tmp/camp.ini"
"$fs" campaign "$tmp/camp.ini" --set run.duration_s=0.05 -j 1 --out "$disk/c" >/dev/null 2>&1
cp "$disk/c/summary.json" "$tmp/before.json"
if command -v gnuplot >/dev/null; then
    # room for the text files (a 4 KiB block each, schema.sql too) but not for the chart: gnuplot exits 0 having written part of it
    # (--fresh: the same campaign again into its finished folder would otherwise do nothing)
    leave 43192
    "$fs" campaign "$tmp/camp.ini" --set run.duration_s=0.05 -j 1 --out "$disk/c" --fresh >/dev/null 2>"$tmp/err1"
    s1=$?
    check '[ "$s1" -eq 4 ] && grep -q "success.png: cannot write: No space left on device" "$tmp/err1"'
    check 'cmp -s "$tmp/before.json" "$disk/c/summary.json" && [ -z "$(ls -a "$disk" | grep -e partial -e lock -e tmp)" ]'
else
    echo "skipped: gnuplot is not installed (the truncated-chart case of finding 4)"
fi
# footsim's own PNG writer on a full disk: the system's words, not libpng's
leave 4096
"$fs" terrain terrains/rough.ini --png "$disk/map.png" >/dev/null 2>"$tmp/err2"
s2=$?
check '[ "$s2" -eq 4 ] && grep -q "map.png: cannot write: No space left on device" "$tmp/err2" && ! grep -q libpng "$tmp/err2"'
check '[ ! -e "$disk/map.png" ] && [ -z "$(ls -a "$disk" | grep tmp)" ]'
finish
