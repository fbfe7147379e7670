# A sweep of a constraint's bound: 'gnuplot front.gp' in this folder draws front.png from front.csv
# (each search's best, and the foot's file design; the bounds' labels above and below in turn, so
# that two bests at one point stay apart).
if (!exists("out")) out = 'front.png'
search = 'optimize_every_terrain_shape'
objective = 'objective: the parameters' . "'" . ' weighted sum, each over its min'
quantity = 'foot_mass_kg'
obj = 9
set terminal pngcairo size 720,480 noenhanced font 'sans,10'
set output out
set datafile separator ','
set title 'Design search ' . search . ': each bound''s best'
set xlabel quantity . ' of the design (the swept bound''s quantity)'
set ylabel objective
set key outside bottom center horizontal
set grid
plot 'front.csv' skip 1 using (strcol(1) eq 'best' && column(obj + 2) > 0 ? column(obj + 1) : 1/0):obj with points pt 6 ps 1.5 lc rgb '#999999' title 'best, missing a target', \
     'front.csv' skip 1 using (column(obj + 4) == 1 ? column(obj + 1) : 1/0):obj with linespoints pt 7 lw 2 lc rgb '#b2182b' title 'front (targets met)', \
     'front.csv' skip 1 using (strcol(1) eq 'best' && int(column(0)) % 2 ? column(obj + 1) : 1/0):obj:(sprintf('%g', column(2))) with labels offset 0,1 notitle, \
     'front.csv' skip 1 using (strcol(1) eq 'best' && !(int(column(0)) % 2) ? column(obj + 1) : 1/0):obj:(sprintf('%g', column(2))) with labels offset 0,-1 notitle, \
     'front.csv' skip 1 using (strcol(1) eq 'file' ? column(obj + 1) : 1/0):obj with points pt 5 ps 1.5 lc rgb '#2166ac' title 'the foot''s file design'
