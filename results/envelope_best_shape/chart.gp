# A campaign's chart: 'gnuplot chart.gp' in this folder draws success.png.
if (!exists("out")) out = 'success.png'
# the names shown, as gnuplot strings: data, never code
campaign = 'envelope_best'
series1 = 'best, flat'
series2 = 'best, complex_uneven'
key1 = 'robot.com_height_m'
set terminal pngcairo size 960,540 noenhanced font 'sans,11'
set output out
set title 'Campaign ' . campaign . ': success rate with 95 % Wilson interval (20 seeds each)'
set ylabel 'success rate (landed / trials)'
set yrange [-0.05:1.05]
set ytics 0,0.2,1
set grid ytics
set key outside right top noenhanced
set arrow from graph 0, first 0 to graph 1, first 0 nohead lc rgb 'gray30'
set xlabel key1
plot 'chart.dat' index 0 using 1:3:4 with filledcurves fs transparent solid 0.2 noborder lc 1 notitle, \
     '' index 0 using 1:2 with linespoints lw 2 dt 1 pt 7 lc 1 title series1, \
     'chart.dat' index 1 using 1:3:4 with filledcurves fs transparent solid 0.2 noborder lc 1 notitle, \
     '' index 1 using 1:2 with linespoints lw 2 dt 1 pt 9 lc 1 title series2
