# A design search's trade-off: 'gnuplot pareto.gp' in this folder draws pareto.png from
# evaluations.csv (every candidate that ran) and pareto.csv (its Pareto front).
if (!exists("out")) out = 'pareto.png'
search = 'optimize_every_terrain_bilinear_band_stop'
objective = 'objective: the parameters' . "'" . ' weighted sum, each over its min'
col = 7
set terminal pngcairo size 720,480 noenhanced font 'sans,10'
set output out
set datafile separator ','
set title 'Design search ' . search . ': the candidates that ran and their Pareto front'
set xlabel objective
set ylabel 'shortfall: the targets missed, summed (0: every target met)'
set key top right
set grid
set yrange [-0.05:*]
plot 'evaluations.csv' skip 1 using col:(column(col + 2) == 0 ? column(col + 1) : 1/0) with points pt 6 lc rgb '#999999' title 'candidates', \
     'pareto.csv' skip 1 using col:(column(col + 1)) with linespoints pt 7 lw 2 lc rgb '#b2182b' title 'Pareto front'
