# The chart of campaign landing: 'gnuplot chart.gp' in this folder draws success.png.
if (!exists("out")) out = 'success.png'
set terminal pngcairo size 1120,540 noenhanced font 'sans,11'
set output out
set title 'Campaign landing: success rate with 95 % Wilson interval (10 seeds each)'
set ylabel 'success rate (landed / trials)'
set yrange [-0.05:1.05]
set ytics 0,0.2,1
set grid ytics
set key outside right top
set arrow from graph 0, first 0 to graph 1, first 0 nohead lc rgb 'gray30'
set xrange [-0.6:4.4]
set xtics scale 0
set boxwidth 0.1 absolute
set style fill solid 0.6 border -1
set xlabel 'terrain'
set label "a thin bar under the zero line:\nno trial landed" at graph 1.03, graph 0.05 font 'sans,9' tc rgb 'gray30'
plot 'chart.dat' using ($0-0.35):2:xtic(1) with boxes lc 1 title 'biomimetic, single_tall', \
     '' using ($0-0.35):(column(2) == 0 ? -0.025 : 1/0) with boxes lc 1 notitle, \
     '' using ($0-0.35):3:(0):(column(4) - column(3)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     'chart.dat' using ($0-0.25):5 with boxes lc 2 title 'biomimetic, drop_weight', \
     '' using ($0-0.25):(column(5) == 0 ? -0.025 : 1/0) with boxes lc 2 notitle, \
     '' using ($0-0.25):6:(0):(column(7) - column(6)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     'chart.dat' using ($0-0.15):8 with boxes lc 3 title 'biomimetic, rig', \
     '' using ($0-0.15):(column(8) == 0 ? -0.025 : 1/0) with boxes lc 3 notitle, \
     '' using ($0-0.15):9:(0):(column(10) - column(9)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     'chart.dat' using ($0-0.05):11 with boxes lc 4 title 'biomimetic, biped', \
     '' using ($0-0.05):(column(11) == 0 ? -0.025 : 1/0) with boxes lc 4 notitle, \
     '' using ($0-0.05):12:(0):(column(13) - column(12)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     'chart.dat' using ($0+0.05):14 with boxes lc 5 title 'flat, single_tall', \
     '' using ($0+0.05):(column(14) == 0 ? -0.025 : 1/0) with boxes lc 5 notitle, \
     '' using ($0+0.05):15:(0):(column(16) - column(15)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     'chart.dat' using ($0+0.15):17 with boxes lc 6 title 'flat, drop_weight', \
     '' using ($0+0.15):(column(17) == 0 ? -0.025 : 1/0) with boxes lc 6 notitle, \
     '' using ($0+0.15):18:(0):(column(19) - column(18)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     'chart.dat' using ($0+0.25):20 with boxes lc 7 title 'flat, rig', \
     '' using ($0+0.25):(column(20) == 0 ? -0.025 : 1/0) with boxes lc 7 notitle, \
     '' using ($0+0.25):21:(0):(column(22) - column(21)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle, \
     'chart.dat' using ($0+0.35):23 with boxes lc 8 title 'flat, biped', \
     '' using ($0+0.35):(column(23) == 0 ? -0.025 : 1/0) with boxes lc 8 notitle, \
     '' using ($0+0.35):24:(0):(column(25) - column(24)) with vectors heads size screen 0.004,90 lw 1 lc rgb 'black' notitle
