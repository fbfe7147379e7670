# 'gnuplot precision.gp' in this folder draws precision.png from precision.csv.
if (!exists("out")) out = 'precision.png'
set datafile separator ','
sel(scene, stepper, spring, col) = (strcol(1) eq scene && strcol(2) eq stepper && strcol(4) eq spring && $16 == 1 && strcol(13) ne 'blown_up') ? column(col) : NaN
subs(scene, col) = (strcol(1) eq scene && $16 > 1 && strcol(13) ne 'blown_up') ? column(col) : NaN
dflt(scene, col) = (strcol(1) eq scene && $15 == 1 && strcol(13) eq 'ok') ? column(col) : NaN
$front0 << EOD
3.10688,1.61669e-06
7.84797,6.46479e-06
35.0256,1.90988e-05
47.2884,2.75293e-05
54.7553,3.09604e-05
80.6514,3.95098e-05
86.9742,6.45492e-05
117.936,9.16952e-05
152.627,0.000160365
207.705,0.000188361
305.145,0.00031235
434.16,0.000347706
806.419,0.000366404
807.501,0.000444589
1377.78,0.000734278
1670.75,0.00147003
EOD
$front1 << EOD
0.28472,3.16578e-06
0.701514,6.72864e-06
4.52663,1.20333e-05
6.20159,2.06563e-05
8.81938,3.6576e-05
9.42323,4.46672e-05
10.1793,4.69368e-05
16.1904,9.17705e-05
44.6742,0.000182385
89.5591,0.000234554
98.3696,0.000366403
108.593,0.00632431
EOD
$front2 << EOD
0.183623,4.25472e-06
1.08044,1.6253e-05
1.60592,2.82733e-05
6.38544,6.94409e-05
10.1223,7.36689e-05
12.2306,0.000150912
14.9004,0.000261294
15.8235,0.000436729
19.4767,0.000518482
47.7399,0.000876024
49.8104,0.00104803
71.6172,0.00168524
80.5245,0.00242214
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
set multiplot layout 2,2
s = 'landing_flat'
set title 'flat foot landing on rough ground'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front0 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'landing_biomimetic'
set title 'biomimetic foot landing on flat ground (drop_weight)'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front1 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'landing_biomimetic_rough'
set title 'biomimetic foot landing on rough ground (drop_weight)'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front2 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
unset multiplot
