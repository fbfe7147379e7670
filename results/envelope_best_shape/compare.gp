# The shape search's best foot's envelope beside the first best's and Table I's (docs/landing.md, The
# best foot found): the success rate of single_tall against its centre-of-mass height, with 95 %
# Wilson intervals, on even (left) and complex uneven (right) ground, 20 seeds a point: the shape
# search's best (summary.csv here: scenarios/envelope_best.ini with --set
# foot.best.file=feet/best_every_terrain_shape.ini), the 3-seed search's best (../envelope_best/)
# and Table I's foot (../envelope/summary.csv, scenarios/envelope.ini's scale-1 column). Run in this folder: 'gnuplot compare.gp'
# draws compare.png. Columns are read by number: here 4 the height, 11-13 the rate and its interval;
# in the envelope's 4 the scale, 5 the height, 12-14 the rate and its interval. The best foot's points
# are drawn 4 % right of their height and Table I's 4 % left, so that the intervals stay apart.
set terminal pngcairo size 1120,480 noenhanced font 'sans,10'
set output 'compare.png'
set datafile separator comma
set multiplot layout 1,2 title 'The shape search''s best foot against the first best and Table I: single_tall landed, 20 seeds a point, 95 % Wilson intervals'
set logscale x
set xrange [0.016:0.37]
set xtics (0.02, 0.035, 0.05, 0.1, 0.2, 0.3)
set yrange [-0.05:1.05]
set ytics 0,0.2,1
set grid ytics
set xlabel 'robot.com_height_m'
set ylabel 'success rate (landed / trials)'
set bmargin 7
set key at graph 0.5, graph -0.17 center top maxrows 3 reverse Left samplen 3 font 'sans,9'
on(t) = strstrt(strcol(2), t) == 1
best(t) = on(t) ? column(11) : 1/0
env(t, s) = on(t) && column(4) == s ? column(12) : 1/0
do for [t in 'flat complex_uneven'] {
    set title (t eq 'flat' ? 'even ground (flat)' : 'complex uneven ground')
    plot 'summary.csv' every ::1 using ($4 * 1.04):(best(t)):12:13 with yerrorlines lw 2 pt 7 lc rgb '#1b7837' title 'best, toes splayed and larger (feet/best_every_terrain_shape.ini)', \
         '../envelope_best/summary.csv' every ::1 using 4:(best(t)):12:13 with yerrorlines lw 1 dt 2 pt 6 lc rgb '#2166ac' title 'first best (feet/best_every_terrain.ini)', \
         '../envelope/summary.csv' every ::1 using ($5 / 1.04):(env(t, 1)):13:14 with yerrorlines lw 2 pt 5 lc rgb '#b2182b' title 'Table I (feet/biomimetic.ini)'
}
unset multiplot
