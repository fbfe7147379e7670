# footsim bench stability: soil against step size (run from this folder: gnuplot -e "out='x.png'" stability_soil.gp)
set terminal pngcairo size 1200,900 noenhanced font 'sans,10'
set output out
set datafile separator ','
set multiplot layout 2,2 title 'footsim bench stability: soil'
set logscale x
set xrange [5e-6:2e-2]
set format x '%.0e'
set xlabel 'step h, s'
set ylabel 'elastic slope K_e of dry sand (flat foot, drop weight), Pa/m'
set logscale y
set offsets graph 0.05, graph 0.05, graph 0.08, graph 0.08
set key outside bottom center horizontal
set linetype 11 lc rgb '#2ca02c'
set linetype 12 lc rgb '#ff9f1c'
set linetype 13 lc rgb '#d62728'
set title 'implicit springs, step'
ok(p) = strcol(1) eq 'soil' && strcol(2) eq 'step' && strcol(4) eq 'implicit' && column(12) == p
plot for [p=0:2] 'stability.csv' every ::1 using (ok(p) ? $5 : NaN):10:(11 + p) with points pt 5 ps 1.8 lc variable title word('stable drifting blown_up', p + 1), \
     'stability.csv' every ::1 using (ok(0) + ok(1) + ok(2) && 'implicit' eq 'explicit' ? $23 : NaN):10 with points pt 2 ps 1.5 lc rgb 'black' title 'predicted explicit limit'
set title 'explicit springs, step'
ok(p) = strcol(1) eq 'soil' && strcol(2) eq 'step' && strcol(4) eq 'explicit' && column(12) == p
plot for [p=0:2] 'stability.csv' every ::1 using (ok(p) ? $5 : NaN):10:(11 + p) with points pt 5 ps 1.8 lc variable title word('stable drifting blown_up', p + 1), \
     'stability.csv' every ::1 using (ok(0) + ok(1) + ok(2) && 'explicit' eq 'explicit' ? $23 : NaN):10 with points pt 2 ps 1.5 lc rgb 'black' title 'predicted explicit limit'
set title 'implicit springs, quickstep'
ok(p) = strcol(1) eq 'soil' && strcol(2) eq 'quickstep' && strcol(4) eq 'implicit' && column(12) == p
plot for [p=0:2] 'stability.csv' every ::1 using (ok(p) ? $5 : NaN):10:(11 + p) with points pt 5 ps 1.8 lc variable title word('stable drifting blown_up', p + 1), \
     'stability.csv' every ::1 using (ok(0) + ok(1) + ok(2) && 'implicit' eq 'explicit' ? $23 : NaN):10 with points pt 2 ps 1.5 lc rgb 'black' title 'predicted explicit limit'
set title 'explicit springs, quickstep'
ok(p) = strcol(1) eq 'soil' && strcol(2) eq 'quickstep' && strcol(4) eq 'explicit' && column(12) == p
plot for [p=0:2] 'stability.csv' every ::1 using (ok(p) ? $5 : NaN):10:(11 + p) with points pt 5 ps 1.8 lc variable title word('stable drifting blown_up', p + 1), \
     'stability.csv' every ::1 using (ok(0) + ok(1) + ok(2) && 'explicit' eq 'explicit' ? $23 : NaN):10 with points pt 2 ps 1.5 lc rgb 'black' title 'predicted explicit limit'
unset multiplot
