#!/bin/sh
# Soil through the command (docs/soil.md): a small soil campaign (2 feet x dry sand x 2 seeds, a short
# window, a 2 mm grid) writes the same bytes with -j 1 and -j 2; bad soils are refused with file:line
# and exit 2 before anything runs. Usage: cli_soil.sh path/to/footsim (run from the source folder).
. "$(dirname "$0")/cli_check.sh"

. "$(dirname "$0")/small_campaign.sh"
sed -i "s#file = $PWD/terrains/simply_uneven.ini#file = $PWD/terrains/soils/dry_sand.ini#" "$tmp/small.ini"
sed -i "s#^seeds = 3#seeds = 2#" "$tmp/small.ini"
soil() { nice "$fs" campaign "$tmp/small.ini" --set run.duration_s=0.1 --set soil.grid_m=0.002 "$@"; }
soil -j 1 --out "$tmp/j1" >/dev/null 2>"$tmp/j1.err"
check_that "soil campaign -j 1 exits 0" [ $? -eq 0 ]
soil -j 2 --out "$tmp/j2" >/dev/null 2>"$tmp/j2.err"
check_that "soil campaign -j 2 exits 0" [ $? -eq 0 ]
for f in summary.csv trials.csv summary.json; do
    check_that "$f the same with -j 1 and -j 2" cmp -s "$tmp/j1/$f" "$tmp/j2/$f"
done
check 'grep -q "soils/dry_sand.ini" "$tmp/j1/summary.json"' # the soil is among the inputs (provenance)

# refusals, before anything is written
printf '[soil]\nmodel = bekker\n\n[bekker]\nn = 0\n' >"$tmp/n.ini"
expect 2 "n.ini:5" -- run scenarios/static_load.ini --set "scenario.terrain=$tmp/n.ini" --out "$tmp/no1"
printf '[soil]\nmodel = rft\ndepth_m = 0.05\n' >"$tmp/rft.ini"
expect 2 "zeta_N_per_m3" -- run scenarios/static_load.ini --set "scenario.terrain=$tmp/rft.ini" --out "$tmp/no2"
expect 2 "max_nodes" -- run scenarios/static_load.ini --set scenario.terrain=../terrains/soils/dry_sand.ini \
    --set soil.grid_m=1e-4 --set soil.max_nodes=1000 --out "$tmp/no3"
check '[ ! -e "$tmp/no1" ] && [ ! -e "$tmp/no2" ] && [ ! -e "$tmp/no3" ]'
finish
