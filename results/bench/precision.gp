# 'gnuplot precision.gp' in this folder draws precision.png from precision.csv.
if (!exists("out")) out = 'precision.png'
set datafile separator ','
sel(scene, stepper, spring, col) = (strcol(1) eq scene && strcol(2) eq stepper && strcol(4) eq spring && strcol(13) ne 'blown_up') ? column(col) : NaN
dflt(scene, col) = (strcol(1) eq scene && $15 == 1 && strcol(13) eq 'ok') ? column(col) : NaN
$front0 << EOD
0.195973,4.06955e-09
3.46452,4.06955e-09
6.98258,8.13814e-09
17.3283,2.03531e-08
34.7073,4.08183e-08
58.8649,2.31127e-07
149.139,5.75475e-07
297.303,1.14107e-06
598.088,2.24282e-06
1492.87,5.33415e-06
3012.55,9.86865e-06
EOD
$front1 << EOD
3.41224,6.64455e-06
8.46887,2.80005e-05
8.62072,2.8004e-05
16.664,4.15589e-05
16.8724,4.15619e-05
33.068,8.3386e-05
33.4998,8.33881e-05
81.756,0.000131871
163.655,0.000207473
325.136,0.000344914
856.999,0.00106487
1757.38,0.00147003
EOD
$front2 << EOD
0.396198,2.87027e-06
0.596614,7.20252e-06
0.98854,1.43247e-05
1.9566,2.43026e-05
3.87103,4.62482e-05
9.42072,8.3877e-05
18.8347,0.000169683
37.7817,0.000402369
84.825,0.000852187
176.828,0.00416992
EOD
$front3 << EOD
0.265976,3.83532e-06
0.527155,5.45579e-06
1.83594,6.09252e-05
8.78704,0.000138784
17.9432,0.000367625
31.557,0.000509101
78.8709,0.0012986
123.529,0.00237938
EOD
set terminal pngcairo size 1400,1100 font ',11'
set output out
set logscale xy
set format y '10^{%L}'
set format x '10^{%L}'
set xlabel 'real-time factor (simulated s per wall s)'
set ylabel 'largest ankle error (m)'
set grid
set key bottom right font ',9'
set multiplot layout 2,2
s = 'chain'
set title 'pinned chain against the planar reference'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front0 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'landing_flat'
set title 'flat foot landing on rough ground'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front1 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'landing_biomimetic'
set title 'biomimetic foot landing on flat ground (drop_weight)'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front2 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'landing_biomimetic_rough'
set title 'biomimetic foot landing on rough ground (drop_weight)'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front3 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
unset multiplot
