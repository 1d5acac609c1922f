set terminal pngcairo size 900,470 font 'sans,10'
set termoption noenhanced
set output 'scaling-gas.png'
set logscale xy
set grid
set key outside right top font ',9'
set format x '%.0f'
set xlabel 'balls'
set ylabel 'engine ns per ball-step'
set bmargin at screen 0.1276595744680851
set title 'Step cost against ball count, gas'
plot 'scaling-gas-home-seed.dat' with linespoints lc rgb '#D55E00' dt 1 lw 2 pt 7 ps 0.8 title 'home-seed', 'scaling-gas-home.dat' with linespoints lc rgb '#0072B2' dt 1 lw 2 pt 7 ps 0.8 title 'home', 'scaling-gas-home-events.dat' with linespoints lc rgb '#0072B2' dt 3 lw 2 pt 7 ps 0.8 title 'home/events', 'scaling-gas-exact.dat' with linespoints lc rgb '#000000' dt 1 lw 2 pt 7 ps 0.8 title 'exact', 'scaling-gas-box2d-tuned.dat' with linespoints lc rgb '#E69F00' dt 1 lw 2 pt 7 ps 0.8 title 'box2d/tuned', 'scaling-gas-box2d-stock.dat' with linespoints lc rgb '#E69F00' dt 2 lw 2 pt 7 ps 0.8 title 'box2d/stock', 'scaling-gas-bullet-tuned.dat' with linespoints lc rgb '#CC79A7' dt 1 lw 2 pt 7 ps 0.8 title 'bullet/tuned', 'scaling-gas-bullet-stock.dat' with linespoints lc rgb '#CC79A7' dt 2 lw 2 pt 7 ps 0.8 title 'bullet/stock', 'scaling-gas-chipmunk-tuned.dat' with linespoints lc rgb '#009E73' dt 1 lw 2 pt 7 ps 0.8 title 'chipmunk/tuned', 'scaling-gas-chipmunk-stock.dat' with linespoints lc rgb '#009E73' dt 2 lw 2 pt 7 ps 0.8 title 'chipmunk/stock', 'scaling-gas-lammps-hooke.dat' with linespoints lc rgb '#56B4E9' dt 1 lw 2 pt 7 ps 0.8 title 'lammps/hooke', 'scaling-gas-lammps-hertz.dat' with linespoints lc rgb '#56B4E9' dt 2 lw 2 pt 7 ps 0.8 title 'lammps/hertz', 'scaling-gas-ode-tuned.dat' with linespoints lc rgb '#AA4499' dt 1 lw 2 pt 7 ps 0.8 title 'ode/tuned', 'scaling-gas-ode-stock.dat' with linespoints lc rgb '#AA4499' dt 2 lw 2 pt 7 ps 0.8 title 'ode/stock'
