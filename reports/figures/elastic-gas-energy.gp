set terminal pngcairo size 900,740 font 'sans,10'
set termoption noenhanced
set output 'elastic-gas-energy.png'
set multiplot layout 2,1
set lmargin at screen 0.09
set rmargin at screen 0.7
set title 'Energy over time, elastic-gas: each engine''s first profile'
set logscale y
set xlabel 'time (s)'
set ylabel 'E / E0 (log scale)'
set yrange [0.0001<*:*<10000]
set grid
set key outside right top font ',9'
plot 'elastic-gas-energy-home-seed.dat' with lines lw 2 dt 1 lc rgb '#777777' title 'home-seed', 'elastic-gas-energy-home.dat' with lines lw 2 dt 1 lc rgb '#0072B2' title 'home', 'elastic-gas-energy-exact.dat' with lines lw 2 dt 1 lc rgb '#000000' title 'exact', 'elastic-gas-energy-box2d-tuned.dat' with lines lw 2 dt 1 lc rgb '#E69F00' title 'box2d/tuned', 'elastic-gas-energy-bullet-tuned.dat' with lines lw 2 dt 1 lc rgb '#CC79A7' title 'bullet/tuned', 'elastic-gas-energy-chipmunk-tuned.dat' with lines lw 2 dt 1 lc rgb '#009E73' title 'chipmunk/tuned', 'elastic-gas-energy-lammps-hooke.dat' with lines lw 2 dt 1 lc rgb '#56B4E9' title 'lammps/hooke', 'elastic-gas-energy-ode-tuned.dat' with lines lw 2 dt 1 lc rgb '#661100' title 'ode/tuned', 'elastic-gas-energy-rapier-tuned.dat' with lines lw 2 dt 1 lc rgb '#999933' title 'rapier/tuned', 'elastic-gas-energy-matter-tuned.dat' with lines lw 2 dt 1 lc rgb '#332288' title 'matter/tuned', 'elastic-gas-energy-planck-tuned.dat' with lines lw 2 dt 1 lc rgb '#882255' title 'planck/tuned', 'elastic-gas-energy-box2d3-tuned.dat' with lines lw 2 dt 1 lc rgb '#D55E00' title 'box2d3/tuned'
set title 'elastic-gas: the other profiles (dashed)'
plot 'elastic-gas-energy-exact.dat' with lines lw 1.5 dt 1 lc rgb '#000000' title 'exact (reference)', 'elastic-gas-energy-home-events.dat' with lines lw 2 dt 3 lc rgb '#0072B2' title 'home/events', 'elastic-gas-energy-box2d-stock.dat' with lines lw 2 dt 2 lc rgb '#E69F00' title 'box2d/stock', 'elastic-gas-energy-bullet-stock.dat' with lines lw 2 dt 2 lc rgb '#CC79A7' title 'bullet/stock', 'elastic-gas-energy-chipmunk-stock.dat' with lines lw 2 dt 2 lc rgb '#009E73' title 'chipmunk/stock', 'elastic-gas-energy-lammps-hertz.dat' with lines lw 2 dt 2 lc rgb '#56B4E9' title 'lammps/hertz', 'elastic-gas-energy-ode-stock.dat' with lines lw 2 dt 2 lc rgb '#661100' title 'ode/stock', 'elastic-gas-energy-rapier-stock.dat' with lines lw 2 dt 2 lc rgb '#999933' title 'rapier/stock', 'elastic-gas-energy-matter-stock.dat' with lines lw 2 dt 2 lc rgb '#332288' title 'matter/stock', 'elastic-gas-energy-planck-stock.dat' with lines lw 2 dt 2 lc rgb '#882255' title 'planck/stock', 'elastic-gas-energy-box2d3-stock.dat' with lines lw 2 dt 2 lc rgb '#D55E00' title 'box2d3/stock'
unset multiplot
