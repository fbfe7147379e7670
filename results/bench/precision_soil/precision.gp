# 'gnuplot precision.gp' in this folder draws precision.png from precision.csv.
if (!exists("out")) out = 'precision.png'
set datafile separator ','
sel(scene, stepper, spring, col) = (strcol(1) eq scene && strcol(2) eq stepper && strcol(4) eq spring && $16 == 1 && strcol(13) ne 'blown_up') ? column(col) : NaN
subs(scene, col) = (strcol(1) eq scene && $16 > 1 && strcol(13) ne 'blown_up') ? column(col) : NaN
dflt(scene, col) = (strcol(1) eq scene && $15 == 1 && strcol(13) eq 'ok') ? column(col) : NaN
$front0 << EOD
1.18165,1.53007e-05
1.24962,1.53007e-05
2.38079,1.58833e-05
2.50266,1.58833e-05
5.94388,1.763e-05
6.34391,1.76301e-05
7.96075,1.99353e-05
12.0274,2.14692e-05
12.8027,2.14693e-05
15.9212,2.9659e-05
24.0962,4.76885e-05
25.5483,4.76893e-05
25.5863,5.06368e-05
31.8581,6.15264e-05
50.142,0.000103228
62.9219,0.000129573
64.6682,0.000129595
79.2091,0.000163732
120.593,0.000265567
126.59,0.000265586
157.655,0.000331159
238.361,0.000536913
255.097,0.000536985
309.3,0.000669901
602.643,0.00136279
623.296,0.00136816
1001.73,0.0028145
1228.78,0.0028145
EOD
set terminal pngcairo size 1400,1100 font ',11'
set output out
set logscale xy
set format y '10^{%L}'
set format x '10^{%L}'
set xlabel 'real-time factor (simulated s per wall s)'
set ylabel 'largest ankle error (m)'
set grid
set key bottom right font ',8' spacing 0.9
set multiplot layout 1,2
s = 'flat_rig_dry_sand'
set title 'flat foot on dry sand (rig; reference at 1e-5 s on the 0.5 mm grid)'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front0 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
unset multiplot
