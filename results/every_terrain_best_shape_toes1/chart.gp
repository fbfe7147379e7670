# A campaign's chart: 'gnuplot chart.gp' in this folder draws success.png.
if (!exists("out")) out = 'success.png'
# the names shown, as gnuplot strings: data, never code
campaign = 'every_terrain'
series1 = 'biomimetic, single_tall'
series2 = 'biomimetic, drop_weight'
series3 = 'flat, single_tall'
series4 = 'flat, drop_weight'
terrain1 = 'flat'
terrain2 = 'simply_uneven'
terrain3 = 'complex_uneven'
set terminal pngcairo size 960,540 noenhanced font 'sans,11'
set output out
set title 'Campaign ' . campaign . ': success rate with 95 % Wilson interval (20 seeds each)'
set ylabel 'success rate (landed / trials)'
set yrange [-0.05:1.05]
set ytics 0,0.2,1
set grid ytics
set key outside right top noenhanced
set arrow from graph 0, first 0 to graph 1, first 0 nohead lc rgb 'gray30'
set yrange [-0.05:1.12]
set xrange [-0.6:2.4]
set xtics scale 0 noenhanced (terrain1 0, terrain2 1, terrain3 2)
set boxwidth 0.177778 absolute
set style fill solid 0.6 border -1
set xlabel 'terrain'
set label "a thin bar under the zero line:\nno trial landed" at graph 1.03, graph 0.05 font 'sans,9' tc rgb 'gray30'
plot 'chart.dat' using ($0-0.311111):2 with boxes fs solid 0.75 lc 1 title series1, \
     '' using ($0-0.311111):(column(2) == 0 ? -0.025 : 1/0) with boxes fs solid 0.75 lc 1 notitle, \
     '' using ($0-0.311111):3:(0):(column(4) - column(3)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     '' using ($0-0.311111):(column(5) == 1 ? 1.07 : 1/0) with points pt 6 ps 1.2 lc 1 notitle, \
     '' using ($0-0.311111):(column(5) == 0 ? 1.07 : 1/0) with points pt 2 ps 1.2 lc 1 notitle, \
     'chart.dat' using ($0+0.133333):6 with boxes fs solid 0.25 lc 1 title series2, \
     '' using ($0+0.133333):(column(6) == 0 ? -0.025 : 1/0) with boxes fs solid 0.25 lc 1 notitle, \
     '' using ($0+0.133333):7:(0):(column(8) - column(7)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     '' using ($0+0.133333):(column(9) == 1 ? 1.07 : 1/0) with points pt 6 ps 1.2 lc 1 notitle, \
     '' using ($0+0.133333):(column(9) == 0 ? 1.07 : 1/0) with points pt 2 ps 1.2 lc 1 notitle, \
     'chart.dat' using ($0-0.133333):10 with boxes fs solid 0.75 lc 2 title series3, \
     '' using ($0-0.133333):(column(10) == 0 ? -0.025 : 1/0) with boxes fs solid 0.75 lc 2 notitle, \
     '' using ($0-0.133333):11:(0):(column(12) - column(11)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     '' using ($0-0.133333):(column(13) == 1 ? 1.07 : 1/0) with points pt 6 ps 1.2 lc 2 notitle, \
     '' using ($0-0.133333):(column(13) == 0 ? 1.07 : 1/0) with points pt 2 ps 1.2 lc 2 notitle, \
     'chart.dat' using ($0+0.311111):14 with boxes fs solid 0.25 lc 2 title series4, \
     '' using ($0+0.311111):(column(14) == 0 ? -0.025 : 1/0) with boxes fs solid 0.25 lc 2 notitle, \
     '' using ($0+0.311111):15:(0):(column(16) - column(15)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     '' using ($0+0.311111):(column(17) == 1 ? 1.07 : 1/0) with points pt 6 ps 1.2 lc 2 notitle, \
     '' using ($0+0.311111):(column(17) == 0 ? 1.07 : 1/0) with points pt 2 ps 1.2 lc 2 notitle, \
     keyentry with points pt 6 lc rgb 'black' title 'law: stands', \
     keyentry with points pt 2 lc rgb 'black' title 'law: topples'
