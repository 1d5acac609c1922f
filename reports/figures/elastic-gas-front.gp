set terminal pngcairo size 900,520 font 'sans,10'
set output 'elastic-gas-front.png'
set title 'Equal accuracy on elastic-gas: cost against error, every configuration tried'
set xlabel 'error / spec: the worst term over its bound (at most 1 meets the spec)'
set ylabel 'cost (ns per ball per scene step)'
set logscale xy
set format x '%g'
set format y '%g'
set grid
set key outside right top
set arrow from 1, graph 0 to 1, graph 1 nohead dt 2 lw 1.5 lc rgb '#000000'
set xrange [*:2]
plot 'elastic-gas-front-home.dat' index 0 with lines lw 2 dt 1 lc rgb '#0072B2' title 'home', 'elastic-gas-front-home.dat' index 1 with points pt 7 ps 1.2 lc rgb '#0072B2' notitle, 'elastic-gas-front-home.dat' index 2 with points pt 6 ps 1.2 lc rgb '#0072B2' notitle, 'elastic-gas-front-home-events.dat' index 0 with lines lw 2 dt 3 lc rgb '#0072B2' title 'home/events', 'elastic-gas-front-home-events.dat' index 1 with points pt 13 ps 1.2 lc rgb '#0072B2' notitle, 'elastic-gas-front-home-events.dat' index 2 with points pt 12 ps 1.2 lc rgb '#0072B2' notitle, 'elastic-gas-front-exact.dat' index 0 with lines lw 2 dt 1 lc rgb '#000000' title 'exact', 'elastic-gas-front-exact.dat' index 1 with points pt 7 ps 1.2 lc rgb '#000000' notitle, 'elastic-gas-front-exact.dat' index 2 with points pt 6 ps 1.2 lc rgb '#000000' notitle, 'elastic-gas-front-chipmunk-tuned.dat' index 0 with lines lw 2 dt 1 lc rgb '#009E73' title 'chipmunk/tuned', 'elastic-gas-front-chipmunk-tuned.dat' index 1 with points pt 7 ps 1.2 lc rgb '#009E73' notitle, 'elastic-gas-front-chipmunk-tuned.dat' index 2 with points pt 6 ps 1.2 lc rgb '#009E73' notitle, 'elastic-gas-front-chipmunk-stock.dat' index 0 with lines lw 2 dt 2 lc rgb '#009E73' title 'chipmunk/stock', 'elastic-gas-front-chipmunk-stock.dat' index 1 with points pt 5 ps 1.2 lc rgb '#009E73' notitle, 'elastic-gas-front-chipmunk-stock.dat' index 2 with points pt 4 ps 1.2 lc rgb '#009E73' notitle, 'elastic-gas-front-picks.dat' with points pt 6 ps 3 lw 2 lc rgb '#000000' title 'the picks'
