set terminal pngcairo size 900,740 font 'sans,10'
set termoption noenhanced
set output 'elastic-gas-energy.png'
set xlabel 'time (s)'
set ylabel 'E / E0 (log scale)'
set logscale y
set yrange [1e-4<*:*<1e4]
set grid
set key outside right top font ',9'
set lmargin at screen 0.09
set rmargin at screen 0.70
set multiplot layout 2,1
set title 'Energy over time, elastic-gas: each engine''s first profile'
plot 'elastic-gas-energy-home-seed.dat' with lines lw 2 lc rgb '#777777' dt 1 title 'home-seed', 'elastic-gas-energy-home.dat' with lines lw 2 lc rgb '#0072B2' dt 1 title 'home', 'elastic-gas-energy-exact.dat' with lines lw 2 lc rgb '#000000' dt 1 title 'exact', 'elastic-gas-energy-box2d-tuned.dat' with lines lw 2 lc rgb '#E69F00' dt 1 title 'box2d/tuned', 'elastic-gas-energy-bullet-tuned.dat' with lines lw 2 lc rgb '#CC79A7' dt 1 title 'bullet/tuned', 'elastic-gas-energy-chipmunk-tuned.dat' with lines lw 2 lc rgb '#009E73' dt 1 title 'chipmunk/tuned', 'elastic-gas-energy-lammps-hooke.dat' with lines lw 2 lc rgb '#56B4E9' dt 1 title 'lammps/hooke', 'elastic-gas-energy-ode-tuned.dat' with lines lw 2 lc rgb '#661100' dt 1 title 'ode/tuned', 'elastic-gas-energy-rapier-tuned.dat' with lines lw 2 lc rgb '#999933' dt 1 title 'rapier/tuned', 'elastic-gas-energy-matter-tuned.dat' with lines lw 2 lc rgb '#332288' dt 1 title 'matter/tuned', 'elastic-gas-energy-planck-tuned.dat' with lines lw 2 lc rgb '#882255' dt 1 title 'planck/tuned', 'elastic-gas-energy-box2d3-tuned.dat' with lines lw 2 lc rgb '#D55E00' dt 1 title 'box2d3/tuned'
set title 'elastic-gas: the other profiles (dashed)'
plot 'elastic-gas-energy-exact.dat' with lines lw 1.5 lc rgb '#000000' dt 1 title 'exact (reference)', 'elastic-gas-energy-home-events.dat' with lines lw 2 lc rgb '#0072B2' dt 3 title 'home/events', 'elastic-gas-energy-box2d-stock.dat' with lines lw 2 lc rgb '#E69F00' dt 2 title 'box2d/stock', 'elastic-gas-energy-bullet-stock.dat' with lines lw 2 lc rgb '#CC79A7' dt 2 title 'bullet/stock', 'elastic-gas-energy-chipmunk-stock.dat' with lines lw 2 lc rgb '#009E73' dt 2 title 'chipmunk/stock', 'elastic-gas-energy-lammps-hertz.dat' with lines lw 2 lc rgb '#56B4E9' dt 2 title 'lammps/hertz', 'elastic-gas-energy-ode-stock.dat' with lines lw 2 lc rgb '#661100' dt 2 title 'ode/stock', 'elastic-gas-energy-rapier-stock.dat' with lines lw 2 lc rgb '#999933' dt 2 title 'rapier/stock', 'elastic-gas-energy-matter-stock.dat' with lines lw 2 lc rgb '#332288' dt 2 title 'matter/stock', 'elastic-gas-energy-planck-stock.dat' with lines lw 2 lc rgb '#882255' dt 2 title 'planck/stock', 'elastic-gas-energy-box2d3-stock.dat' with lines lw 2 lc rgb '#D55E00' dt 2 title 'box2d3/stock'
unset multiplot
