#!/bin/sh
# Soil through the command (docs/soil.md): a small soil campaign (2 feet x dry sand x 2 seeds, a short
# window, a 2 mm grid) writes the same bytes with -j 1 and -j 2; a trial's final surface is written and
# loads back as a heightmap; a walk over a soil section labels its steps on the rigid ground so and its
# steps on the sand "on the soil"; bad soils are refused with file:line and exit 2 before anything runs. Usage: cli_soil.sh path/to/footsim (run from the source folder).
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

# the final surface (docs/soil.md): a trial on soil writes it as surface.png (16-bit), surface.csv in
# mm (RFC 4180), its provenance and surface.ini, a terrain file that loads the PNG back as rigid
# heightmap ground: its heights are the CSV's within half the PNG's quantum (and the CSV's 1e-6 mm),
# at the deepest print and at three other nodes; footsim terrain draws it
"$fs" trial scenarios/landing_trial.ini --set scenario.design=feet/flat.ini --set robot.design=robots/rig.ini \
    --set scenario.terrain=../terrains/soils/dry_sand.ini --set soil.grid_m=0.002 --set run.duration_s=0.15 \
    --out "$tmp/surf" >"$tmp/surf.out" 2>&1
check_that "a trial on soil with --out exits 0" [ $? -eq 0 ]
for f in surface.png surface.csv surface.ini surface.provenance.json; do
    check_that "$f written" [ -s "$tmp/surf/$f" ]
done
check 'grep -q "surface.png, .csv and .ini" "$tmp/surf.out"'
check '/usr/bin/python3 "$(dirname "$0")/csv_check.py" csv "$tmp/surf/surface.csv:surface_mm:print_mm" >&2'
check 'head -1 "$tmp/surf/surface.csv" | grep -q "^x_mm,y_mm,surface_mm,print_mm"'
quantum=$(sed -n 's/.*"png_quantum_m":[[:space:]]*\([0-9.eE+-]*\).*/\1/p' "$tmp/surf/surface.provenance.json")
check '[ -n "$quantum" ]'
deepest=$(awk -F, 'NR > 1 && $4 + 0 > d { d = $4 + 0; row = $0 } END { print row }' "$tmp/surf/surface.csv" | tr -d '\r')
check_that "a print deeper than 1 mm (what the check is about)" awk -v d="$(echo "$deepest" | cut -d, -f4)" 'BEGIN { exit !(d > 1) }'
rows=$(awk 'NR == 2 || NR == 500 || NR == 1500' "$tmp/surf/surface.csv" | tr -d '\r')
for row in $deepest $rows; do
    x=$(echo "$row" | awk -F, '{ printf "%.12f", $1 / 1000 }') y=$(echo "$row" | awk -F, '{ printf "%.12f", $2 / 1000 }')
    z_mm=$(echo "$row" | cut -d, -f3)
    h=$("$fs" terrain "$tmp/surf/surface.ini" --height "$x" "$y")
    check_that "surface at $x $y: $h m against $z_mm mm within half of $quantum m" \
        awk -v h="$h" -v z="$z_mm" -v q="$quantum" 'BEGIN { d = h * 1000 - z; if (d < 0) d = -d; exit !(d <= q * 500 + 2e-6) }'
done
"$fs" terrain "$tmp/surf/surface.ini" --png "$tmp/surf_map.png" >/dev/null 2>&1
check_that "footsim terrain draws the surface" [ -s "$tmp/surf_map.png" ]

# footsim terrain names a soil on a line of its own (model, name, depth, grid); rigid ground has none
check '"$fs" terrain terrains/soils/dry_sand.ini | grep -q "^  soil: bekker (dry_sand), 0.1 m deep .* grid 0.5 mm"'
check '! "$fs" terrain terrains/flat.ini | grep -q "soil"'

# the walking machine over a soil section (terrains/sand_section.ini, docs/soil.md, A soil section): its
# first three steps are on the rigid ground before the sand and say so, the fifth is on the sand
"$fs" walk scenarios/walking_sand.ini --set soil.grid_m=0.002 --set walk.steps=5 >"$tmp/walk.out" 2>&1
check_that "a walk over a soil section exits 0" [ $? -eq 0 ]
check 'grep -q "^  step 1 on rigid ground: sinkage" "$tmp/walk.out"'
check '! grep -q "^  step [123] on the soil" "$tmp/walk.out"'
check 'grep -q "^  step 5 on the soil: sinkage" "$tmp/walk.out"'

# refusals, before anything is written
# refused N NAME TEXT PATTERN: a terrain file NAME.ini of TEXT (a printf format), laid under the static
# load with `run`, is refused with exit 2 and "NAME.ini:PATTERN" on stderr (into $tmp/noN, never made)
refused() {
    printf "$3" >"$tmp/$2.ini"
    expect 2 "$2.ini:$4" -- run scenarios/static_load.ini --set "scenario.terrain=$tmp/$2.ini" --out "$tmp/no$1"
}
refused 1 n '[soil]\nmodel = bekker\n\n[bekker]\nn = 0\n' "5"
# an rft soil that does not give zeta: [soil] model's line without [rft], the [rft] header's with it; the key to add
refused 2 rft '[soil]\nmodel = rft\ndepth_m = 0.05\n' "2: .*zeta_N_per_m3 .*: add zeta_N_per_m3"
refused 5 rft2 '[soil]\nmodel = rft\n\n[rft]\ndensity_kg_per_m3 = 1500\n' \
    "4: an rft soil needs \[rft\] zeta_N_per_m3 .*: add zeta_N_per_m3"
expect 2 "max_nodes" -- run scenarios/static_load.ini --set scenario.terrain=../terrains/soils/dry_sand.ini \
    --set soil.grid_m=1e-4 --set soil.max_nodes=1000 --out "$tmp/no3"
# the grid's memory cap, judged once the feet's region is known, still names the file and grid_m's line
refused 4 cap '[soil]\nmodel = bekker\ngrid_m = 1e-4\nmax_nodes = 1000\n\n[bekker]\nn = 1.1\n' \
    "3: the soil's grid_m of 0.0001 m .* over \[soil\] max_nodes = 1000"
# phi's range is [0, 90): said so for a negative phi too
refused 6 phi '[soil]\nmodel = bekker\n\n[bekker]\nfriction_deg = -1\n' "5: friction_deg = '-1' .*\[0, 90) deg"
# a [bekker] section without [soil] would leave the ground rigid: refused at its header
refused 7 nosoil '[terrain]\nkind = flat\n\n[bekker]\nn = 1.1\n' "4: \[bekker\] has no effect without a \[soil\] section"
# a bekker soil without [bekker] would run on the keys' defaults, no soil: refused at [soil] model
refused 8 nobekker '[soil]\nmodel = bekker\ndepth_m = 0.05\n' "2: a bekker soil needs a \[bekker\] section .*terrains/soils/"
# a bekker soil with no bearing strength (k_c = k_phi = 0: the foot would fall through to the bedrock):
# refused at k_phi's line with what would be right, nothing written
refused 10 nobearing '[soil]\nmodel = bekker\ndepth_m = 0.1\n\n[bekker]\nn = 1\nk_phi_N_per_m_n2 = 0\nk_c_N_per_m_n1 = 0\n' \
    "7: a bekker soil with k_c_N_per_m_n1 = 0 and k_phi_N_per_m_n2 = 0 bears no load.*give k_phi_N_per_m_n2 > 0 or k_c_N_per_m_n1 > 0"
check '[ ! -e "$tmp/no10" ]'
# a tolerance from --set on a soil names the --set (it read "(set in code)"): a soil takes a tolerance
# (its rejected steps undone), so the refusal here is impact_substeps'
expect 2 "^footsim: --set run.tolerance_m: tolerance_m = 0.0001 cannot be used here: impact_substeps" -- trial \
    scenarios/landing_trial.ini --set scenario.terrain=../terrains/soils/dry_sand.ini --set run.tolerance_m=1e-4 \
    --set run.impact_substeps=4 --out "$tmp/no9"
for i in 1 2 3 4 5 6 7 8 9; do check "[ ! -e \"\$tmp/no$i\" ]"; done

# a run on a soil stopped by the checks says what bounds its step there (docs/soil.md, Explicit forces):
# the biomimetic foot on dry sand at 5e-3 s, whose toe hinges drift past the loop check at 0.185 s
nice "$fs" trial scenarios/landing_trial.ini --set scenario.terrain=../terrains/soils/dry_sand.ini \
    --set run.step_s=5e-3 --seed 1 --out "$tmp/big" >"$tmp/big.out" 2>&1
check_that "a soil run past its step's bound exits 3" [ $? -eq 3 ]
check_that "its message names the soil's bound" grep -q "failed_numerics.*on a soil the step is bounded lower" "$tmp/big.out"
# whole in the written trial too (its failure text is shorter than the command's message)
check_that "trial.json keeps the hint whole" grep -q "on a soil the step is bounded lower (docs/soil.md, Explicit forces), or set run.tolerance_m" "$tmp/big/trial.json"
# explicit springs past their own bound are the cause there, not the soil: no soil hint
nice "$fs" trial scenarios/landing_trial.ini --set scenario.terrain=../terrains/soils/dry_sand.ini \
    --set run.step_s=5e-3 --set run.springs=explicit --seed 1 --out "$tmp/big_expl" >"$tmp/big_expl.out" 2>&1
check_that "explicit springs past their bound: exit 3" [ $? -eq 3 ]
check_that "and the springs named, not the soil" sh -c "grep -q 'explicit springs are stable below' \"$tmp/big_expl.out\" && ! grep -q 'on a soil' \"$tmp/big_expl.out\""
# the same step on rigid ground runs, and its message would not be the soil's
nice "$fs" trial scenarios/landing_trial.ini --set run.step_s=5e-3 --seed 1 --out "$tmp/big_rigid" >"$tmp/big_rigid.out" 2>&1
check_that "the same step on rigid ground runs through" [ $? -eq 0 ]
check_that "and says nothing of a soil" sh -c "! grep -q 'on a soil' \"$tmp/big_rigid.out\""
finish
