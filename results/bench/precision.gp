# 'gnuplot precision.gp' in this folder draws precision.png from precision.csv.
if (!exists("out")) out = 'precision.png'
set datafile separator ','
sel(scene, stepper, spring, col) = (strcol(1) eq scene && strcol(2) eq stepper && strcol(4) eq spring && $16 == 1 && strcol(13) ne 'blown_up') ? column(col) : NaN
subs(scene, col) = (strcol(1) eq scene && $16 > 1 && strcol(13) ne 'blown_up') ? column(col) : NaN
dflt(scene, col) = (strcol(1) eq scene && $15 == 1 && strcol(13) eq 'ok') ? column(col) : NaN
$front0 << EOD
0.198228,4.06955e-09
3.49754,4.06955e-09
7.04737,8.13814e-09
17.7283,2.03531e-08
34.6434,4.08183e-08
59.7883,2.31127e-07
151.346,5.75475e-07
301.091,1.14107e-06
603.983,2.24282e-06
1499.49,5.33415e-06
2949.81,9.86865e-06
EOD
$front1 << EOD
3.47459,6.64455e-06
8.49379,2.80005e-05
8.62017,2.8004e-05
17.2321,4.15589e-05
34.3124,8.3386e-05
83.9177,0.000131871
84.6069,0.000132011
106.563,0.000182169
123.419,0.000182195
167.514,0.000207473
171.719,0.000207675
304.657,0.000277466
337.074,0.000344914
340.527,0.000344918
492.749,0.000359307
663.028,0.000359533
923.277,0.000380465
1271.05,0.000382791
1524.25,0.000734278
1885.82,0.00147003
EOD
$front2 << EOD
0.412045,2.87027e-06
0.608504,7.20252e-06
1.00679,1.43247e-05
1.96145,2.43026e-05
3.86229,4.62482e-05
7.67638,7.41229e-05
8.81425,8.03002e-05
9.6006,8.3877e-05
9.81299,9.57866e-05
13.9422,9.67127e-05
17.4294,0.000105929
23.3726,0.000134351
29.9596,0.000137664
56.8951,0.000167029
72.6535,0.000212425
106.865,0.000217527
142.89,0.000366403
160.133,0.000734278
178.191,0.00416992
EOD
$front3 << EOD
0.272934,3.83532e-06
0.540267,5.45579e-06
1.88839,6.09252e-05
5.50995,9.52372e-05
8.36225,0.000104301
9.01531,0.000138784
10.4025,0.000143457
11.0308,0.000150318
13.4201,0.000237472
18.8008,0.000367625
23.0826,0.000431952
32.5866,0.000509101
59.2666,0.0005871
89.634,0.00117914
131.017,0.00237938
EOD
$front4 << EOD
5.76026,8.37095e-06
11.3161,8.88554e-06
28.4501,1.82299e-05
165.418,2.5982e-05
262.498,5.13861e-05
328.826,6.70808e-05
342.654,6.88963e-05
634.561,8.33892e-05
1485.3,0.000107846
2848.48,0.000182466
4009.75,0.000366404
4942.62,0.000734279
5675.95,0.00147003
EOD
$front5 << EOD
2.64872,1.73343e-06
3.14612,6.56107e-06
7.8925,6.93567e-06
8.62728,2.92792e-05
15.8408,3.98066e-05
54.3152,5.43709e-05
69.1484,7.53204e-05
87.8502,8.66027e-05
110.338,0.000107365
136.457,0.000151929
158.081,0.00016066
172.048,0.000186833
215.457,0.0002117
274.572,0.000228867
316.368,0.000263202
345.241,0.000378321
495.852,0.000519685
666.578,0.000550341
786.858,0.000672721
865.244,0.000856658
950.941,0.00104084
1276.76,0.00110215
1472.16,0.00122478
1765.08,0.00297927
EOD
$front6 << EOD
1.75126,1.85156e-06
2.62954,2.94568e-06
3.37472,5.66118e-06
6.56335,6.87057e-06
7.81099,8.02602e-06
8.51531,2.03299e-05
13.1539,3.19152e-05
26.3207,3.92437e-05
52.1127,4.8584e-05
66.7798,5.3489e-05
78.0185,7.80504e-05
83.5897,7.83623e-05
105.838,8.64362e-05
134.504,0.000106242
154.904,0.000128545
169.096,0.000170238
203.741,0.000194532
265.587,0.000214152
309.484,0.000253392
343.876,0.000331872
475.054,0.000412388
638.399,0.000458372
898.602,0.000611654
1186.38,0.000734279
1502.65,0.000979529
1621.16,0.00314252
EOD
$front7 << EOD
4.85248,4.14992e-06
9.58788,5.5316e-06
21.8297,8.87636e-06
128.107,1.413e-05
208.131,1.92668e-05
279.376,3.48645e-05
513.477,3.80037e-05
673.675,7.84792e-05
1177.4,0.000122915
2261.73,0.000182466
3081.44,0.000366404
3495.67,0.000734279
4204.61,0.00147003
EOD
$front8 << EOD
1.32355,2.19245e-06
2.67302,4.04211e-06
7.24123,8.448e-06
15.2562,1.54654e-05
47.8516,2.39057e-05
62.3026,3.26329e-05
77.535,3.99071e-05
99.8136,4.92217e-05
102.459,5.32487e-05
130.278,6.69679e-05
202.896,9.15273e-05
256.464,0.000125862
867.559,0.000182466
1081.6,0.000366404
EOD
$front9 << EOD
0.684153,6.4182e-06
8.6264,0.000123504
30.128,0.000129683
51.7952,0.000132658
65.16,0.000138537
120.94,0.000162685
189.546,0.000182466
295.819,0.000366404
380.648,0.000734279
EOD
$front10 << EOD
11.4979,6.11065e-06
28.7031,1.33548e-05
157.921,1.77433e-05
254.124,2.82738e-05
315.803,3.39539e-05
342.628,4.43917e-05
619.299,4.6632e-05
846.048,8.17173e-05
1480.67,0.000105595
2862.69,0.000182466
3977.19,0.000366404
5002.05,0.000734279
5822.89,0.00314308
EOD
$front11 << EOD
3.04569,2.62715e-08
3.85679,1.60198e-06
5.94453,1.60198e-06
6.12172,1.62177e-06
14.861,6.84326e-06
15.2576,6.84352e-06
19.3246,1.72419e-05
29.732,1.7242e-05
30.6235,1.72632e-05
61.0177,3.18812e-05
93.7043,5.1705e-05
119.514,5.46639e-05
136.609,6.01066e-05
148.742,8.04465e-05
149.878,8.05373e-05
187.927,8.18104e-05
216.227,9.12817e-05
234.714,0.000104083
272.166,0.000115443
301.633,0.000163186
358.798,0.000180529
464.656,0.000191549
550.196,0.000202628
607.823,0.000322009
834.564,0.000328884
1106.06,0.000346367
1343.45,0.000415353
1605.27,0.000479004
2163.61,0.000530673
2667.66,0.000734279
3026.87,0.00147003
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
