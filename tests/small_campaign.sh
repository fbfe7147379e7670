# Sourced by the campaign, resume, shard and signal tests (run from the source folder, $tmp set): writes
# $tmp/trial.ini (campaign_test_trial.ini with absolute paths, so that the test may edit it) and
# $tmp/small.ini, 2 feet x 1 terrain x 3 seeds = 6 trials; camp runs it with a short window (the
# numbers do not matter to these tests) through "$fs"; $files are the files a campaign writes;
# opt_ini writes $tmp/opt.ini, a one-evaluation design search of small.ini (give small.ini an
# expectation first).
cp scenarios/campaign_test_trial.ini "$tmp/trial.ini"
sed -i "s#^design = feet/#design = $PWD/scenarios/feet/#; s#^terrain = ../terrains/#terrain = $PWD/terrains/#; s#^design = robots/#design = $PWD/scenarios/robots/#" "$tmp/trial.ini"
cat >"$tmp/small.ini" <<END
[campaign]
trial = trial.ini
seeds = 3

[foot.bio]
file = $PWD/scenarios/feet/biomimetic.ini

[foot.flat]
file = $PWD/scenarios/feet/flat.ini

[terrain.bumpy]
file = $PWD/terrains/simply_uneven.ini
END
files="summary.json summary.csv summary.md trials.csv schema.sql chart.dat chart.gp"
command -v gnuplot >/dev/null 2>&1 && files="$files success.png"
camp() { nice "$fs" campaign "$tmp/small.ini" --set run.duration_s=0.15 "$@"; }
opt_ini() {
    printf '[optimize]\ncampaign = small.ini\nobjective = least_stiff\nmax_evaluations = 1\nvalidation_first_seed = 101\n' >"$tmp/opt.ini"
    printf '[param.k]\nkey = springs.k_d1_N_per_m\nmin = 12000\nmax = 24000\nstart = 12000\n' >>"$tmp/opt.ini"
}
