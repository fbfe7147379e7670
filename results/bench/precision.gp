# 'gnuplot precision.gp' in this folder draws precision.png from precision.csv.
if (!exists("out")) out = 'precision.png'
set datafile separator ','
sel(scene, stepper, spring, col) = (strcol(1) eq scene && strcol(2) eq stepper && strcol(4) eq spring && strcol(13) ne 'blown_up') ? column(col) : NaN
dflt(scene, col) = (strcol(1) eq scene && $15 == 1 && strcol(13) eq 'ok') ? column(col) : NaN
$front0 << EOD
0.168225,4.06955e-09
2.94382,4.06955e-09
5.92295,8.13814e-09
14.973,2.03531e-08
25.3155,4.08183e-08
25.4107,1.15709e-07
50.9188,2.31127e-07
126.977,5.75475e-07
255.041,1.14107e-06
512.354,2.24282e-06
1287.97,5.33415e-06
2567.16,9.86865e-06
EOD
$front1 << EOD
0.152623,2.1477e-05
0.165926,2.27201e-05
0.696718,2.41955e-05
2.06274,3.52554e-05
3.84001,9.03693e-05
8.02792,0.0001604
17.1744,0.000286351
19.049,0.000557714
41.8011,0.000576031
87.7194,0.00138511
156.578,0.00147003
EOD
$front2 << EOD
0.0347156,0.000252883
0.0630859,0.000391507
0.149394,0.000775232
0.204533,0.00106618
0.450573,0.00132253
1.25461,0.00147337
2.35316,0.00154453
4.48225,0.0020841
13.7021,0.00332047
29.4683,0.00747035
EOD
set terminal pngcairo size 1800,600 font ',11'
set output out
set logscale xy
set format y '10^{%L}'
set format x '10^{%L}'
set xlabel 'real-time factor (simulated s per wall s)'
set ylabel 'largest ankle error (m)'
set grid
set key bottom right font ',9'
set multiplot layout 1,3
s = 'chain'
set title 'pinned chain against the planar reference'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front0 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'landing_flat'
set title 'flat foot landing on rough ground'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front1 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
s = 'landing_biomimetic'
set title 'biomimetic foot landing on rough ground'
plot 'precision.csv' skip 1 using (sel(s,'step','implicit',12)):(sel(s,'step','implicit',6)) with points pt 7 ps 1 lc rgb '#1f77b4' title 'dWorldStep, implicit springs', \
     '' skip 1 using (sel(s,'step','explicit',12)):(sel(s,'step','explicit',6)) with points pt 5 ps 1 lc rgb '#ff7f0e' title 'dWorldStep, explicit', \
     '' skip 1 using (sel(s,'quickstep','implicit',12)):(sel(s,'quickstep','implicit',6)) with points pt 6 ps 1 lc rgb '#2ca02c' title 'QuickStep, implicit', \
     '' skip 1 using (sel(s,'quickstep','explicit',12)):(sel(s,'quickstep','explicit',6)) with points pt 4 ps 1 lc rgb '#d62728' title 'QuickStep, explicit', \
     '' skip 1 using (dflt(s,12)):(dflt(s,6)) with points pt 3 ps 3 lw 2 lc rgb 'black' title 'scenario default', \
     $front2 using 1:2 with lines lw 2 lc rgb 'black' title 'Pareto front'
unset multiplot
