# The chart of campaign soil: 'gnuplot chart.gp' in this folder draws success.png.
if (!exists("out")) out = 'success.png'
set terminal pngcairo size 960,540 noenhanced font 'sans,11'
set output out
set title 'Campaign soil: success rate with 95 % Wilson interval (1 seeds each)'
set ylabel 'success rate (landed / trials)'
set yrange [-0.05:1.05]
set ytics 0,0.2,1
set grid ytics
set key outside right top
set arrow from graph 0, first 0 to graph 1, first 0 nohead lc rgb 'gray30'
set xrange [-0.6:3.4]
set xtics scale 0
set boxwidth 0.2 absolute
set style fill solid 0.6 border -1
set xlabel 'terrain'
set label "a thin bar under the zero line:\nno trial landed" at graph 1.03, graph 0.05 font 'sans,9' tc rgb 'gray30'
plot 'chart.dat' using ($0-0.3):2:xtic(1) with boxes lc 1 title 'biomimetic, drop_weight', \
     '' using ($0-0.3):(column(2) == 0 ? -0.025 : 1/0) with boxes lc 1 notitle, \
     '' using ($0-0.3):3:(0):(column(4) - column(3)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     'chart.dat' using ($0-0.1):5 with boxes lc 2 title 'biomimetic, biped', \
     '' using ($0-0.1):(column(5) == 0 ? -0.025 : 1/0) with boxes lc 2 notitle, \
     '' using ($0-0.1):6:(0):(column(7) - column(6)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     'chart.dat' using ($0+0.1):8 with boxes lc 3 title 'flat, drop_weight', \
     '' using ($0+0.1):(column(8) == 0 ? -0.025 : 1/0) with boxes lc 3 notitle, \
     '' using ($0+0.1):9:(0):(column(10) - column(9)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     'chart.dat' using ($0+0.3):11 with boxes lc 4 title 'flat, biped', \
     '' using ($0+0.3):(column(11) == 0 ? -0.025 : 1/0) with boxes lc 4 notitle, \
     '' using ($0+0.3):12:(0):(column(13) - column(12)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle
