# The chart of campaign roughness: 'gnuplot chart.gp' in this folder draws success.png.
if (!exists("out")) out = 'success.png'
set terminal pngcairo size 960,540 noenhanced font 'sans,11'
set output out
set title 'Campaign roughness: success rate with 95 % Wilson interval (5 seeds each)'
set ylabel 'success rate (landed / trials)'
set yrange [-0.05:1.05]
set ytics 0,0.2,1
set grid ytics
set key outside right top
set arrow from graph 0, first 0 to graph 1, first 0 nohead lc rgb 'gray30'
set xlabel 'rough.rms_m'
plot 'chart.dat' index 0 using 1:3:4 with filledcurves fs transparent solid 0.2 noborder lc 1 notitle, \
     '' index 0 using 1:2 with linespoints lw 2 pt 7 lc 1 title 'biomimetic, single_tall', \
     'chart.dat' index 1 using 1:3:4 with filledcurves fs transparent solid 0.2 noborder lc 2 notitle, \
     '' index 1 using 1:2 with linespoints lw 2 pt 7 lc 2 title 'biomimetic, drop_weight', \
     'chart.dat' index 2 using 1:3:4 with filledcurves fs transparent solid 0.2 noborder lc 3 notitle, \
     '' index 2 using 1:2 with linespoints lw 2 pt 7 lc 3 title 'flat, single_tall', \
     'chart.dat' index 3 using 1:3:4 with filledcurves fs transparent solid 0.2 noborder lc 4 notitle, \
     '' index 3 using 1:2 with linespoints lw 2 pt 7 lc 4 title 'flat, drop_weight'
