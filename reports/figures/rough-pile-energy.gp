set terminal pngcairo size 900,740 font 'sans,10'
set termoption noenhanced
set output 'rough-pile-energy.png'
set xlabel 'time (s)'
set ylabel 'E / E0 (log scale)'
set logscale y
set yrange [1e-4<*:*<1e4]
set grid
set key outside right top font ',9'
set lmargin at screen 0.09
set rmargin at screen 0.70
set multiplot layout 2,1
set title 'Energy over time, rough-pile: each engine''s first profile'
plot 'rough-pile-energy-home.dat' with lines lw 2 lc rgb '#0072B2' dt 1 title 'home', 'rough-pile-energy-box2d-tuned.dat' with lines lw 2 lc rgb '#E69F00' dt 1 title 'box2d/tuned', 'rough-pile-energy-bullet-tuned.dat' with lines lw 2 lc rgb '#CC79A7' dt 1 title 'bullet/tuned', 'rough-pile-energy-chipmunk-tuned.dat' with lines lw 2 lc rgb '#009E73' dt 1 title 'chipmunk/tuned', 'rough-pile-energy-lammps-hooke.dat' with lines lw 2 lc rgb '#56B4E9' dt 1 title 'lammps/hooke', 'rough-pile-energy-ode-tuned.dat' with lines lw 2 lc rgb '#661100' dt 1 title 'ode/tuned', 'rough-pile-energy-rapier-tuned.dat' with lines lw 2 lc rgb '#999933' dt 1 title 'rapier/tuned', 'rough-pile-energy-matter-tuned.dat' with lines lw 2 lc rgb '#332288' dt 1 title 'matter/tuned', 'rough-pile-energy-planck-tuned.dat' with lines lw 2 lc rgb '#882255' dt 1 title 'planck/tuned', 'rough-pile-energy-box2d3-tuned.dat' with lines lw 2 lc rgb '#D55E00' dt 1 title 'box2d3/tuned'
set title 'rough-pile: the other profiles (dashed)'
plot 'rough-pile-energy-home-events.dat' with lines lw 2 lc rgb '#0072B2' dt 3 title 'home/events', 'rough-pile-energy-home-soft.dat' with lines lw 2 lc rgb '#0072B2' dt 2 title 'home/soft', 'rough-pile-energy-box2d-stock.dat' with lines lw 2 lc rgb '#E69F00' dt 2 title 'box2d/stock', 'rough-pile-energy-bullet-stock.dat' with lines lw 2 lc rgb '#CC79A7' dt 2 title 'bullet/stock', 'rough-pile-energy-chipmunk-stock.dat' with lines lw 2 lc rgb '#009E73' dt 2 title 'chipmunk/stock', 'rough-pile-energy-lammps-hertz.dat' with lines lw 2 lc rgb '#56B4E9' dt 2 title 'lammps/hertz', 'rough-pile-energy-ode-stock.dat' with lines lw 2 lc rgb '#661100' dt 2 title 'ode/stock', 'rough-pile-energy-rapier-stock.dat' with lines lw 2 lc rgb '#999933' dt 2 title 'rapier/stock', 'rough-pile-energy-matter-stock.dat' with lines lw 2 lc rgb '#332288' dt 2 title 'matter/stock', 'rough-pile-energy-planck-stock.dat' with lines lw 2 lc rgb '#882255' dt 2 title 'planck/stock', 'rough-pile-energy-box2d3-stock.dat' with lines lw 2 lc rgb '#D55E00' dt 2 title 'box2d3/stock'
unset multiplot
