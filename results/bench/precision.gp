# 'gnuplot precision.gp' in this folder draws precision.png from precision.csv.
if (!exists("out")) out = 'precision.png'
set datafile separator ','
sel(scene, stepper, spring, col) = (strcol(1) eq scene && strcol(2) eq stepper && strcol(4) eq spring && $16 == 1 && strcol(13) ne 'blown_up') ? column(col) : NaN
subs(scene, col) = (strcol(1) eq scene && $16 > 1 && strcol(13) ne 'blown_up') ? column(col) : NaN
dflt(scene, col) = (strcol(1) eq scene && $15 == 1 && strcol(13) eq 'ok') ? column(col) : NaN
$front0 << EOD
0.211023,4.06955e-09
3.62543,4.06955e-09
7.16938,8.13814e-09
18.0581,2.03531e-08
35.9227,4.08183e-08
62.7824,9.47962e-08
155.181,2.39637e-07
310.785,4.86946e-07
623.716,9.99786e-07
1572.7,2.67731e-06
3125.68,6.0722e-06
EOD
$front1 << EOD
3.6298,1.61669e-06
9.02999,6.46479e-06
55.0966,1.90988e-05
69.0199,2.75293e-05
86.5928,3.09604e-05
108.659,3.95098e-05
134.885,6.45492e-05
156.301,9.16952e-05
178.608,0.000160365
309.363,0.000188361
350.447,0.00031235
654.21,0.000347706
1314.07,0.000366404
1667.46,0.000734278
1897.5,0.00147003
EOD
$front2 << EOD
0.428955,3.16578e-06
1.06028,6.72864e-06
6.41584,1.20333e-05
10.1058,2.06563e-05
12.1057,3.6576e-05
15.1055,4.46672e-05
24.5816,9.17705e-05
59.0175,0.000182385
113.741,0.000234554
146.088,0.000366403
150.869,0.000734278
157.657,0.00632431
EOD
$front3 << EOD
0.285892,4.25472e-06
1.45787,1.6253e-05
2.3683,2.82733e-05
2.68862,0.000111632
3.97939,0.000112495
4.23002,0.000130246
13.2317,0.00014782
33.6366,0.000518482
59.2785,0.000876024
59.2929,0.00104803
88.1826,0.00168524
135.774,0.00242214
EOD
$front4 << EOD
5.91322,1.56568e-06
11.4935,1.58428e-06
28.5889,1.11183e-05
164.713,1.15368e-05
264.814,1.92668e-05
326.491,2.17782e-05
354.881,5.07275e-05
644.523,5.34363e-05
867.935,8.77828e-05
1496.75,9.04973e-05
2902.45,0.000250696
4095.24,0.000366404
5084.04,0.000734279
5709.65,0.00147003
EOD
$front5 << EOD
3.51406,2.32016e-06
8.76888,6.93567e-06
8.80903,1.55832e-05
17.6743,1.55832e-05
35.2564,5.2874e-05
58.3015,5.40776e-05
71.9626,5.83695e-05
81.674,6.69533e-05
92.7052,8.66027e-05
115.36,9.4019e-05
131.473,0.000108145
144.107,0.000118456
162.908,0.000135623
174.099,0.000169958
225.7,0.0002117
285.03,0.000228867
329.523,0.000263202
348.436,0.000378098
532.208,0.000519685
696.454,0.000550341
817.095,0.000672721
869.765,0.000856658
1015.16,0.00104084
1356.93,0.00110215
1610.34,0.00122478
1806.47,0.00297691
EOD
$front6 << EOD
3.36696,1.71381e-06
8.37767,8.70114e-06
17.2697,1.54066e-05
34.3833,4.08032e-05
55.5191,4.8584e-05
70.3521,5.3489e-05
81.6955,6.41644e-05
87.9598,7.83623e-05
112.313,8.62103e-05
130.051,0.000101906
140.828,0.000106242
162.419,0.000128543
215.601,0.000194532
276.716,0.000214152
325.497,0.000253392
342.32,0.000331872
502.51,0.000412388
669.555,0.000458372
946.022,0.000611654
1284.72,0.000734279
1569.09,0.000979529
1632.35,0.00314131
EOD
$front7 << EOD
5.02526,1.56568e-06
8.85189,1.70189e-06
23.7381,6.36018e-06
132.922,1.13338e-05
211.96,1.92668e-05
269.918,2.17782e-05
276.237,4.46387e-05
534.407,5.27467e-05
699.254,7.72407e-05
1239.55,9.04973e-05
2386.73,0.000182466
3251.4,0.000366404
3823.62,0.000734279
4327.02,0.00147003
EOD
$front8 << EOD
2.73714,1.71577e-06
6.79821,6.88154e-06
11.9074,1.62537e-05
45.2087,2.39057e-05
53.8309,3.26328e-05
71.3226,3.99071e-05
88.328,4.92217e-05
101.974,6.69678e-05
164.751,9.15273e-05
190.806,0.000125862
694.768,0.000182466
909.503,0.000366404
1370.79,0.000734279
EOD
$front9 << EOD
0.684268,3.90384e-06
1.71037,6.51585e-06
11.8286,1.13338e-05
122.375,0.00014544
172.009,0.000182466
308.74,0.000366404
380.369,0.000734279
EOD
$front10 << EOD
11.4407,1.71577e-06
28.4199,6.88185e-06
163.087,9.02779e-06
258.413,1.51859e-05
322.861,1.97575e-05
351.013,3.20591e-05
645.564,4.00248e-05
873.629,8.17173e-05
1526.63,0.000105595
2947.89,0.000182466
4067.55,0.000366404
5127.36,0.000734279
5691.46,0.00314091
EOD
$front11 << EOD
3.13009,2.62678e-08
6.17681,1.56568e-06
15.5688,7.15648e-06
30.1032,1.45182e-05
30.6285,1.45184e-05
95.6743,1.74467e-05
122.006,2.1151e-05
154.128,2.63695e-05
192.268,3.20203e-05
194.323,3.70961e-05
238.872,4.39341e-05
374.795,5.66608e-05
477.444,8.09156e-05
860.99,0.000136544
1140.32,0.000212649
1665.23,0.000272174
2219.11,0.000405884
2731.29,0.000734279
3066.68,0.00147003
3084.29,0.0481708
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
set multiplot layout 6,2
s = 'chain'
set title 'pinned chain against the planar reference'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front0 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'landing_flat'
set title 'flat foot landing on rough ground'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front1 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'landing_biomimetic'
set title 'biomimetic foot landing on flat ground (drop_weight)'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front2 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'landing_biomimetic_rough'
set title 'biomimetic foot landing on rough ground (drop_weight)'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front3 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_flat'
set title 'flat foot on flat ground (rig)'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front4 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_simply_uneven'
set title 'flat foot on simply uneven ground (rig)'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front5 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_complex_uneven'
set title 'flat foot on complex uneven ground (rig)'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front6 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_stepped'
set title 'flat foot on stepped ground (rig)'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front7 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_heightmap'
set title 'flat foot on the heightmap (rig)'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front8 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_partly_rough'
set title 'flat foot on partly rough ground (rig)'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front9 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_slope'
set title 'flat foot on the slope (rig)'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front10 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_soft'
set title 'flat foot on soft ground (rig)'
plot 'precision.csv' skip 2 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 2 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 2 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 2 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 2 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 2 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front11 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
unset multiplot
