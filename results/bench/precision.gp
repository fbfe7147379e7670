# 'gnuplot precision.gp' in this folder draws precision.png from precision.csv.
if (!exists("out")) out = 'precision.png'
set datafile separator ','
sel(scene, stepper, spring, col) = (strcol(1) eq scene && strcol(2) eq stepper && strcol(4) eq spring && $16 == 1 && strcol(13) ne 'blown_up') ? column(col) : NaN
subs(scene, col) = (strcol(1) eq scene && $16 > 1 && strcol(13) ne 'blown_up') ? column(col) : NaN
dflt(scene, col) = (strcol(1) eq scene && $15 == 1 && strcol(13) eq 'ok') ? column(col) : NaN
$front0 << EOD
0.169765,4.06955e-09
2.31463,4.06955e-09
5.01712,8.13814e-09
9.45724,2.03531e-08
10.8005,2.35554e-08
16.3238,4.08183e-08
19.6903,4.72083e-08
40.7959,9.47962e-08
110.423,2.39637e-07
205.699,4.86946e-07
297.048,9.99786e-07
745.52,2.67731e-06
1484.45,6.0722e-06
EOD
$front1 << EOD
2.42409,1.61669e-06
3.99645,6.46479e-06
4.35175,8.88437e-06
5.66446,1.01398e-05
5.77198,1.05081e-05
25.4725,1.90988e-05
31.0011,2.75293e-05
38.9071,3.09604e-05
74.5586,3.95098e-05
80.503,4.65902e-05
94.9959,8.82636e-05
108.059,9.16952e-05
121.006,0.000160365
195.094,0.000188361
238.698,0.00031235
446.299,0.000347706
611.377,0.000366404
852.89,0.000734278
1287.11,0.00147003
EOD
$front2 << EOD
0.255686,3.16578e-06
0.6424,6.72864e-06
3.75773,1.20333e-05
6.31778,2.06563e-05
6.75496,3.6576e-05
9.94046,4.46672e-05
12.8865,9.17705e-05
28.3847,0.000182385
53.9684,0.000234554
99.1578,0.000366403
102.851,0.000734278
EOD
$front3 << EOD
0.192916,4.25472e-06
0.783402,1.6253e-05
1.27802,2.82733e-05
6.36873,6.94409e-05
8.5717,0.00014782
8.71228,0.000224142
9.94878,0.000459781
23.6575,0.000518482
31.2036,0.000876024
41.418,0.00104803
61.3901,0.00168524
94.9513,0.00242214
EOD
$front4 << EOD
9.0984,1.58428e-06
21.568,1.11183e-05
129.679,1.15368e-05
151.814,2.17782e-05
241.807,4.47689e-05
266.704,4.47878e-05
425.377,5.34363e-05
671.278,8.77828e-05
695.915,9.04973e-05
1621.86,0.000250696
3172.09,0.000366404
EOD
$front5 << EOD
2.48896,2.32016e-06
6.2351,6.93567e-06
6.45101,1.55832e-05
12.4478,1.55832e-05
82.3014,5.02996e-05
93.1407,9.55809e-05
97.7853,0.000118456
124.491,0.000169958
153.794,0.0002117
195.45,0.000228867
211.245,0.000263202
248.826,0.000378098
359.244,0.000519685
479.11,0.000550341
532.047,0.000672721
625.008,0.000856658
680.984,0.00104084
912.802,0.00110215
1106.83,0.00122478
EOD
$front6 << EOD
2.33984,1.71381e-06
5.72122,8.70114e-06
12.1667,1.54066e-05
23.2192,4.08032e-05
38.4959,4.8584e-05
44.5206,4.93834e-05
51.3114,4.94245e-05
55.7515,6.41644e-05
59.4702,7.83623e-05
76.9467,8.62103e-05
87.5663,0.000101906
95.111,0.000106242
111.518,0.000128543
145.378,0.000194532
188.224,0.000214152
214.317,0.000253392
233.844,0.000331872
318.599,0.000412388
462.065,0.000458372
654.127,0.000611654
862.096,0.000734279
1088.08,0.000979529
1161.39,0.00314131
EOD
$front7 << EOD
3.77777,1.56568e-06
6.52441,1.70189e-06
18.1354,6.36018e-06
91.5162,1.13338e-05
151.776,1.92668e-05
199.593,2.17782e-05
204.044,4.46387e-05
373.849,5.27467e-05
515.862,7.72407e-05
921.683,9.04973e-05
1799.25,0.000182466
2470.1,0.000366404
2863.7,0.000734279
3276.6,0.00147003
EOD
$front8 << EOD
1.94784,1.71577e-06
3.98672,6.88154e-06
8.71458,1.62537e-05
32.2419,2.39057e-05
38.4207,3.26328e-05
45.1261,3.99071e-05
60.9691,4.92217e-05
61.0806,4.93796e-05
69.4085,4.93945e-05
74.8511,6.69678e-05
118.399,9.15273e-05
141.502,0.000125862
485.446,0.000182466
651.091,0.000366404
1016.71,0.000734279
EOD
$front9 << EOD
0.436904,3.90384e-06
1.1138,6.51585e-06
7.85548,1.13338e-05
17.261,4.47689e-05
17.9912,9.70146e-05
84.2949,0.00014544
116.073,0.000182466
205.722,0.000366404
256.3,0.000734279
EOD
$front10 << EOD
8.2071,1.71577e-06
16.5608,6.88185e-06
126.766,9.02779e-06
201.939,1.51859e-05
248.795,1.97575e-05
261.95,3.20591e-05
489.827,4.00248e-05
666.885,8.17173e-05
1184.76,0.000105595
2289.12,0.000182466
3171.5,0.000366404
3915.73,0.000734279
4313.95,0.00314091
EOD
$front11 << EOD
2.18789,2.62678e-08
4.6181,1.56568e-06
10.9225,7.15648e-06
21.635,1.45182e-05
23.0485,1.45184e-05
57.9632,1.74467e-05
89.9022,2.1151e-05
94.6519,3.20203e-05
136.557,3.70961e-05
168.479,4.39341e-05
174.038,4.74464e-05
183.541,5.66608e-05
353.854,8.09156e-05
412.234,0.000136544
412.868,0.000166711
853.678,0.000212649
1542.72,0.000405884
2014.19,0.000734279
2258.06,0.00147003
2472.18,0.0481708
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
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front0 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'landing_flat'
set title 'flat foot landing on rough ground'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front1 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'landing_biomimetic'
set title 'biomimetic foot landing on flat ground (drop_weight)'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front2 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'landing_biomimetic_rough'
set title 'biomimetic foot landing on rough ground (drop_weight)'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front3 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_flat'
set title 'flat foot on flat ground (rig)'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front4 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_simply_uneven'
set title 'flat foot on simply uneven ground (rig)'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front5 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_complex_uneven'
set title 'flat foot on complex uneven ground (rig)'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front6 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_stepped'
set title 'flat foot on stepped ground (rig)'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front7 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_heightmap'
set title 'flat foot on the heightmap (rig)'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front8 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_partly_rough'
set title 'flat foot on partly rough ground (rig)'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front9 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_slope'
set title 'flat foot on the slope (rig)'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front10 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'flat_rig_soft'
set title 'flat foot on soft ground (rig)'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (subs(s,12)):(subs(s,6)) with points pt 9 ps 1 lc rgb '#9467bd' title 'touchdown in substeps', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front11 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
unset multiplot
