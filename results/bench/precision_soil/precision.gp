# 'gnuplot precision.gp' in this folder draws precision.png from precision.csv.
if (!exists("out")) out = 'precision.png'
set datafile separator ','
sel(scene, stepper, spring, col) = (strcol(1) eq scene && strcol(2) eq stepper && strcol(4) eq spring && $16 == 1 && strcol(13) ne 'blown_up') ? column(col) : NaN
subs(scene, col) = (strcol(1) eq scene && $16 > 1 && strcol(13) ne 'blown_up') ? column(col) : NaN
dflt(scene, col) = (strcol(1) eq scene && $15 == 1 && strcol(13) eq 'ok') ? column(col) : NaN
$front0 << EOD
0.0192403,4.67552e-06
0.0221645,4.67554e-06
0.0266229,4.67554e-06
0.0434639,5.21854e-06
0.0484672,5.2186e-06
0.1703,1.08493e-05
0.201842,1.58779e-05
0.234754,2.43943e-05
0.283445,2.71721e-05
0.312081,3.24959e-05
0.346121,3.3245e-05
0.363521,5.1612e-05
0.784241,5.37265e-05
0.852748,6.51098e-05
0.970487,6.67022e-05
1.99813,0.000132962
2.63347,0.000269104
2.67628,0.000269129
4.5555,0.000337146
5.90051,0.000539629
7.55931,0.000675787
11.8036,0.0013697
13.127,0.00137451
17.5389,0.00281701
34.4591,0.00281817
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
