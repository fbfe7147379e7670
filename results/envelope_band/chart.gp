# A campaign's chart: 'gnuplot chart.gp' in this folder draws success.png.
if (!exists("out")) out = 'success.png'
# the names shown, as gnuplot strings: data, never code
campaign = 'envelope_band'
series1 = 'biomimetic'
key1 = 'springs.scale'
key2 = 'robot.com_height_m'
set terminal pngcairo size 560,480 noenhanced font 'sans,10'
set output out
set multiplot layout 1,1 title 'Campaign ' . campaign . ': success rate (5 seeds per point) and the laws'
set palette defined (0 '#b2182b', 0.5 '#f7f7f7', 1 '#2166ac')
set cbrange [0:1]
set cblabel 'success rate'
set xlabel key1
set ylabel key2
set logscale x
set xrange [0.6819943394704735:146.80505487867589]
set yrange [0.012499999999999999:0.34999999999999998]
set bmargin 7
set key at graph 0.5, graph -0.19 center top horizontal maxrows 3 reverse Left samplen 2 width 1 font 'sans,9'
set style fill solid 1.0 noborder
set title series1
plot 'chart.dat' index 0 using 1:2:3:4:5:6:7 with boxxyerror lc palette notitle, \
     '' index 0 using 1:($8 == 1 ? $2 : 1/0) with points pt 6 ps 1.2 lc rgb 'black' notitle, \
     '' index 0 using 1:($8 == 0 ? $2 : 1/0) with points pt 2 ps 1.2 lc rgb 'black' notitle, \
     '' index 0 using 1:($10 == 1 ? $2 : 1/0) with points pt 7 ps 0.5 lc rgb 'black' notitle, \
     '' index 0 every 6 using 1:9 with lines lw 2 lc rgb 'black' notitle, \
     '' index 0 every 6 using 1:11 with lines lw 2 dt 2 lc rgb 'black' notitle, \
     keyentry with points pt 6 ps 1.2 lc rgb 'black' title 'static law: stands', \
     keyentry with points pt 2 ps 1.2 lc rgb 'black' title 'static law: topples', \
     keyentry with lines lw 2 lc rgb 'black' title 'its critical height K/(m g)', \
     keyentry with points pt 7 ps 0.5 lc rgb 'black' title 'drop law: stands', \
     keyentry with lines lw 2 dt 2 lc rgb 'black' title 'its highest centre of mass'
unset multiplot
