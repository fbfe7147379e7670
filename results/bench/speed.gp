# footsim bench speed: steps per second and where a step's time goes; out is set by footsim
set terminal pngcairo size 1100,700 font ',10'
set output out
set datafile separator ','
set multiplot layout 2,1
set style data histograms
set style fill solid 0.8 border -1
set boxwidth 0.75
set xtics rotate by -30 left noenhanced
set grid ytics
set key noenhanced
set title 'steps per second on one core (median)'
set logscale y
set ylabel 'steps/s'
plot 'speed.csv' using 8:xtic(1) skip 1 title 'steps/s' lc rgb '#4477aa'
unset logscale y
set title 'share of a step'
set ylabel '%'
set yrange [0:100]
set style histogram rowstacked
set key outside right
plot 'speed.csv' using 12:xtic(1) skip 1 title 'collision' lc rgb '#ddaa33', '' using 13 skip 1 title 'ODE step' lc rgb '#4477aa', '' using 14 skip 1 title 'footsim own code' lc rgb '#bb5566'
unset multiplot
