set terminal pngcairo size 900,740 font 'sans,10'
set termoption noenhanced
set output 'rough-pile-energy.png'
set multiplot layout 2,1
set lmargin at screen 0.09
set rmargin at screen 0.7
set title 'Energy over time, rough-pile: each engine''s first profile'
set logscale y
set xlabel 'time (s)'
set ylabel 'E / E0 (log scale)'
set yrange [0.0001<*:*<10000]
set grid
set key outside right top font ',9'
plot 'rough-pile-energy-home.dat' with lines lw 2 dt 1 lc rgb '#0072B2' title 'home', 'rough-pile-energy-box2d-tuned.dat' with lines lw 2 dt 1 lc rgb '#E69F00' title 'box2d/tuned', 'rough-pile-energy-bullet-tuned.dat' with lines lw 2 dt 1 lc rgb '#CC79A7' title 'bullet/tuned', 'rough-pile-energy-chipmunk-tuned.dat' with lines lw 2 dt 1 lc rgb '#009E73' title 'chipmunk/tuned', 'rough-pile-energy-lammps-hooke.dat' with lines lw 2 dt 1 lc rgb '#56B4E9' title 'lammps/hooke', 'rough-pile-energy-ode-tuned.dat' with lines lw 2 dt 1 lc rgb '#661100' title 'ode/tuned', 'rough-pile-energy-rapier-tuned.dat' with lines lw 2 dt 1 lc rgb '#999933' title 'rapier/tuned', 'rough-pile-energy-matter-tuned.dat' with lines lw 2 dt 1 lc rgb '#332288' title 'matter/tuned', 'rough-pile-energy-planck-tuned.dat' with lines lw 2 dt 1 lc rgb '#882255' title 'planck/tuned', 'rough-pile-energy-box2d3-tuned.dat' with lines lw 2 dt 1 lc rgb '#D55E00' title 'box2d3/tuned'
set title 'rough-pile: the other profiles (dashed)'
plot 'rough-pile-energy-home-events.dat' with lines lw 2 dt 3 lc rgb '#0072B2' title 'home/events', 'rough-pile-energy-home-soft.dat' with lines lw 2 dt 2 lc rgb '#0072B2' title 'home/soft', 'rough-pile-energy-box2d-stock.dat' with lines lw 2 dt 2 lc rgb '#E69F00' title 'box2d/stock', 'rough-pile-energy-bullet-stock.dat' with lines lw 2 dt 2 lc rgb '#CC79A7' title 'bullet/stock', 'rough-pile-energy-chipmunk-stock.dat' with lines lw 2 dt 2 lc rgb '#009E73' title 'chipmunk/stock', 'rough-pile-energy-lammps-hertz.dat' with lines lw 2 dt 2 lc rgb '#56B4E9' title 'lammps/hertz', 'rough-pile-energy-ode-stock.dat' with lines lw 2 dt 2 lc rgb '#661100' title 'ode/stock', 'rough-pile-energy-rapier-stock.dat' with lines lw 2 dt 2 lc rgb '#999933' title 'rapier/stock', 'rough-pile-energy-matter-stock.dat' with lines lw 2 dt 2 lc rgb '#332288' title 'matter/stock', 'rough-pile-energy-planck-stock.dat' with lines lw 2 dt 2 lc rgb '#882255' title 'planck/stock', 'rough-pile-energy-box2d3-stock.dat' with lines lw 2 dt 2 lc rgb '#D55E00' title 'box2d3/stock'
unset multiplot
