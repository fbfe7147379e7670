# 'gnuplot precision.gp' in this folder draws precision.png from precision.csv.
if (!exists("out")) out = 'precision.png'
set datafile separator ','
sel(scene, stepper, spring, col) = (strcol(1) eq scene && strcol(2) eq stepper && strcol(4) eq spring && $16 == 1 && strcol(13) ne 'blown_up') ? column(col) : NaN
subs(scene, col) = (strcol(1) eq scene && $16 > 1 && strcol(13) ne 'blown_up') ? column(col) : NaN
dflt(scene, col) = (strcol(1) eq scene && $15 == 1 && strcol(13) eq 'ok') ? column(col) : NaN
$front0 << EOD
0.214465,4.06955e-09
3.74033,4.06955e-09
7.5038,8.13814e-09
18.808,2.03531e-08
37.6377,4.08183e-08
63.7581,9.47962e-08
158.551,2.39637e-07
319.988,4.86946e-07
639.72,9.99786e-07
1598.77,2.67731e-06
3205.49,6.0722e-06
EOD
$front1 << EOD
3.66533,1.61669e-06
9.13134,6.46479e-06
56.2972,1.90988e-05
70.1792,2.75293e-05
87.486,3.09604e-05
108.072,3.95098e-05
110.997,5.37385e-05
138.549,6.45492e-05
159.151,9.16952e-05
180.036,0.000160365
314.02,0.000188361
359.828,0.00031235
678.472,0.000347706
1326.71,0.000366404
1674.56,0.000734278
1942.7,0.00147003
EOD
$front2 << EOD
0.431074,3.16578e-06
1.07177,6.72864e-06
6.43402,1.20333e-05
10.1284,2.06563e-05
12.7749,3.6576e-05
15.7578,4.46672e-05
24.7113,9.17705e-05
59.5985,0.000182385
114.009,0.000234554
145.773,0.000366403
154.723,0.000734278
159.973,0.00632431
EOD
$front3 << EOD
0.285431,4.25472e-06
1.47134,1.6253e-05
2.35432,2.82733e-05
2.79045,0.000111632
4.05677,0.000112495
4.37787,0.000130246
13.5706,0.00014782
34.7275,0.000518482
61.0853,0.000876024
61.2142,0.00104803
90.2186,0.00168524
140.874,0.00242214
EOD
$front4 << EOD
12.3754,1.58428e-06
31.0054,1.11183e-05
175.148,1.15368e-05
275.91,1.92668e-05
340.827,2.17782e-05
366.078,5.07275e-05
667.424,5.34363e-05
912.964,8.77828e-05
1556.86,9.04973e-05
3000.32,0.000250696
4269.67,0.000366404
5296.55,0.000734279
6139.41,0.00147003
EOD
$front5 << EOD
3.66004,2.32016e-06
9.14981,6.93567e-06
9.21806,1.55832e-05
18.3368,1.55832e-05
36.7113,5.2874e-05
59.3172,5.40776e-05
74.0304,5.83695e-05
81.8113,6.69533e-05
94.4776,8.66027e-05
118.483,9.4019e-05
130.854,0.000108145
148.085,0.000118456
165.707,0.000135623
183.108,0.000169958
231.137,0.0002117
292.593,0.000228867
333.587,0.000263202
368.347,0.000378098
543.666,0.000519685
709.5,0.000550341
830.746,0.000672721
919.216,0.000856658
1028.52,0.00104084
1377.52,0.00110215
1649.66,0.00122478
1906.27,0.00297691
EOD
$front6 << EOD
3.58299,1.71381e-06
8.98853,8.70114e-06
17.9754,1.54066e-05
36.0083,4.08032e-05
56.7314,4.8584e-05
69.2975,5.3489e-05
82.9742,6.41644e-05
89.9109,7.83623e-05
110.645,8.62103e-05
112.833,9.64323e-05
132.783,0.000101906
138.26,0.000106242
166.515,0.000128543
219.961,0.000194532
276.214,0.000214152
328.882,0.000253392
361.21,0.000331872
513.382,0.000412388
666.988,0.000458372
966.141,0.000611654
1279.16,0.000734279
1555.74,0.000979529
1711.58,0.00314131
EOD
$front7 << EOD
4.98778,1.56568e-06
9.03928,1.70189e-06
20.8812,6.36018e-06
139.028,1.13338e-05
221.396,1.92668e-05
283.036,2.17782e-05
285.593,4.46387e-05
554.831,5.27467e-05
731.357,7.72407e-05
1283.49,9.04973e-05
2468.75,0.000182466
3390.5,0.000366404
3979.72,0.000734279
4481.25,0.00147003
EOD
$front8 << EOD
2.73167,1.71577e-06
6.74648,6.88154e-06
13.2608,1.62537e-05
45.8282,2.39057e-05
55.497,3.26328e-05
70.8139,3.99071e-05
88.9103,4.92217e-05
104.914,6.69678e-05
169.152,9.15273e-05
195.006,0.000125862
714.617,0.000182466
908.064,0.000366404
1425.91,0.000734279
EOD
$front9 << EOD
0.676432,3.90384e-06
1.68153,6.51585e-06
12.067,1.13338e-05
126.889,0.00014544
176.396,0.000182466
306.797,0.000366404
386.667,0.000734279
EOD
$front10 << EOD
12.3047,1.71577e-06
30.7539,6.88185e-06
172.203,9.02779e-06
274.868,1.51859e-05
339.4,1.97575e-05
368.75,3.20591e-05
677.892,4.00248e-05
916.6,8.17173e-05
1604.65,0.000105595
3089.24,0.000182466
4309.86,0.000366404
5361.41,0.000734279
6235.27,0.00314091
EOD
$front11 << EOD
3.11045,2.62678e-08
6.32629,1.56568e-06
15.8589,7.15648e-06
30.4849,1.45182e-05
31.6449,1.45184e-05
99.9378,1.74467e-05
126.276,2.1151e-05
158.411,2.63695e-05
197.773,3.20203e-05
200.115,3.70961e-05
248.063,4.39341e-05
384.858,5.66608e-05
491.827,8.09156e-05
886.822,0.000136544
1178.1,0.000212649
1694.97,0.000272174
2289.42,0.000405884
2782.76,0.000734279
3076.68,0.00147003
3124.63,0.0481708
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
