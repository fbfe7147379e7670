# A campaign's chart: 'gnuplot chart.gp' in this folder draws success.png.
if (!exists("out")) out = 'success.png'
# the names shown, as gnuplot strings: data, never code
campaign = 'landing'
series1 = 'biomimetic, single_tall'
series2 = 'biomimetic, drop_weight'
series3 = 'biomimetic, rig'
series4 = 'biomimetic, biped'
series5 = 'flat, single_tall'
series6 = 'flat, drop_weight'
series7 = 'flat, rig'
series8 = 'flat, biped'
terrain1 = 'flat'
terrain2 = 'simply_uneven'
terrain3 = 'complex_uneven'
terrain4 = 'stepped'
terrain5 = 'rough'
set terminal pngcairo size 1120,540 noenhanced font 'sans,11'
set output out
set title 'Campaign ' . campaign . ': success rate with 95 % Wilson interval (10 seeds each)'
set ylabel 'success rate (landed / trials)'
set yrange [-0.05:1.05]
set ytics 0,0.2,1
set grid ytics
set key outside right top noenhanced
set arrow from graph 0, first 0 to graph 1, first 0 nohead lc rgb 'gray30'
set yrange [-0.05:1.12]
set xrange [-0.6:4.4]
set xtics scale 0 noenhanced (terrain1 0, terrain2 1, terrain3 2, terrain4 3, terrain5 4)
set boxwidth 0.0842105 absolute
set style fill solid 0.6 border -1
set xlabel 'terrain'
set label "a thin bar under the zero line:\nno trial landed" at graph 1.03, graph 0.05 font 'sans,9' tc rgb 'gray30'
plot 'chart.dat' using ($0-0.357895):2 with boxes fs solid 0.75 lc 1 title series1, \
     '' using ($0-0.357895):(column(2) == 0 ? -0.025 : 1/0) with boxes fs solid 0.75 lc 1 notitle, \
     '' using ($0-0.357895):3:(0):(column(4) - column(3)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     '' using ($0-0.357895):(column(5) == 1 ? 1.07 : 1/0) with points pt 6 ps 1.2 lc 1 notitle, \
     '' using ($0-0.357895):(column(5) == 0 ? 1.07 : 1/0) with points pt 2 ps 1.2 lc 1 notitle, \
     'chart.dat' using ($0-0.147368):6 with boxes fs solid 0.583 lc 1 title series2, \
     '' using ($0-0.147368):(column(6) == 0 ? -0.025 : 1/0) with boxes fs solid 0.583 lc 1 notitle, \
     '' using ($0-0.147368):7:(0):(column(8) - column(7)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     '' using ($0-0.147368):(column(9) == 1 ? 1.07 : 1/0) with points pt 6 ps 1.2 lc 1 notitle, \
     '' using ($0-0.147368):(column(9) == 0 ? 1.07 : 1/0) with points pt 2 ps 1.2 lc 1 notitle, \
     'chart.dat' using ($0+0.0631579):10 with boxes fs solid 0.417 lc 1 title series3, \
     '' using ($0+0.0631579):(column(10) == 0 ? -0.025 : 1/0) with boxes fs solid 0.417 lc 1 notitle, \
     '' using ($0+0.0631579):11:(0):(column(12) - column(11)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     '' using ($0+0.0631579):(column(13) == 1 ? 1.07 : 1/0) with points pt 6 ps 1.2 lc 1 notitle, \
     '' using ($0+0.0631579):(column(13) == 0 ? 1.07 : 1/0) with points pt 2 ps 1.2 lc 1 notitle, \
     'chart.dat' using ($0+0.273684):14 with boxes fs solid 0.25 lc 1 title series4, \
     '' using ($0+0.273684):(column(14) == 0 ? -0.025 : 1/0) with boxes fs solid 0.25 lc 1 notitle, \
     '' using ($0+0.273684):15:(0):(column(16) - column(15)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     '' using ($0+0.273684):(column(17) == 1 ? 1.07 : 1/0) with points pt 6 ps 1.2 lc 1 notitle, \
     '' using ($0+0.273684):(column(17) == 0 ? 1.07 : 1/0) with points pt 2 ps 1.2 lc 1 notitle, \
     'chart.dat' using ($0-0.273684):18 with boxes fs solid 0.75 lc 2 title series5, \
     '' using ($0-0.273684):(column(18) == 0 ? -0.025 : 1/0) with boxes fs solid 0.75 lc 2 notitle, \
     '' using ($0-0.273684):19:(0):(column(20) - column(19)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     '' using ($0-0.273684):(column(21) == 1 ? 1.07 : 1/0) with points pt 6 ps 1.2 lc 2 notitle, \
     '' using ($0-0.273684):(column(21) == 0 ? 1.07 : 1/0) with points pt 2 ps 1.2 lc 2 notitle, \
     'chart.dat' using ($0-0.0631579):22 with boxes fs solid 0.583 lc 2 title series6, \
     '' using ($0-0.0631579):(column(22) == 0 ? -0.025 : 1/0) with boxes fs solid 0.583 lc 2 notitle, \
     '' using ($0-0.0631579):23:(0):(column(24) - column(23)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     '' using ($0-0.0631579):(column(25) == 1 ? 1.07 : 1/0) with points pt 6 ps 1.2 lc 2 notitle, \
     '' using ($0-0.0631579):(column(25) == 0 ? 1.07 : 1/0) with points pt 2 ps 1.2 lc 2 notitle, \
     'chart.dat' using ($0+0.147368):26 with boxes fs solid 0.417 lc 2 title series7, \
     '' using ($0+0.147368):(column(26) == 0 ? -0.025 : 1/0) with boxes fs solid 0.417 lc 2 notitle, \
     '' using ($0+0.147368):27:(0):(column(28) - column(27)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     '' using ($0+0.147368):(column(29) == 1 ? 1.07 : 1/0) with points pt 6 ps 1.2 lc 2 notitle, \
     '' using ($0+0.147368):(column(29) == 0 ? 1.07 : 1/0) with points pt 2 ps 1.2 lc 2 notitle, \
     'chart.dat' using ($0+0.357895):30 with boxes fs solid 0.25 lc 2 title series8, \
     '' using ($0+0.357895):(column(30) == 0 ? -0.025 : 1/0) with boxes fs solid 0.25 lc 2 notitle, \
     '' using ($0+0.357895):31:(0):(column(32) - column(31)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     '' using ($0+0.357895):(column(33) == 1 ? 1.07 : 1/0) with points pt 6 ps 1.2 lc 2 notitle, \
     '' using ($0+0.357895):(column(33) == 0 ? 1.07 : 1/0) with points pt 2 ps 1.2 lc 2 notitle, \
     keyentry with points pt 6 lc rgb 'black' title 'law: stands', \
     keyentry with points pt 2 lc rgb 'black' title 'law: topples'
