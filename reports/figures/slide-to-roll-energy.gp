set terminal pngcairo size 900,740 font 'sans,10'
set termoption noenhanced
set output 'slide-to-roll-energy.png'
set multiplot layout 2,1
set lmargin at screen 0.09
set rmargin at screen 0.7
set title 'Energy over time, slide-to-roll: each engine''s first profile'
set logscale y
set xlabel 'time (s)'
set ylabel 'E / E0 (log scale)'
set yrange [0.0001<*:*<10000]
set grid
set key outside right top font ',9'
plot 'slide-to-roll-energy-home.dat' with lines lw 2 dt 1 lc rgb '#0072B2' title 'home', 'slide-to-roll-energy-exact.dat' with lines lw 2 dt 1 lc rgb '#000000' title 'exact', 'slide-to-roll-energy-box2d-tuned.dat' with lines lw 2 dt 1 lc rgb '#E69F00' title 'box2d/tuned', 'slide-to-roll-energy-bullet-tuned.dat' with lines lw 2 dt 1 lc rgb '#CC79A7' title 'bullet/tuned', 'slide-to-roll-energy-chipmunk-tuned.dat' with lines lw 2 dt 1 lc rgb '#009E73' title 'chipmunk/tuned', 'slide-to-roll-energy-lammps-hooke.dat' with lines lw 2 dt 1 lc rgb '#56B4E9' title 'lammps/hooke', 'slide-to-roll-energy-ode-tuned.dat' with lines lw 2 dt 1 lc rgb '#661100' title 'ode/tuned', 'slide-to-roll-energy-rapier-tuned.dat' with lines lw 2 dt 1 lc rgb '#999933' title 'rapier/tuned', 'slide-to-roll-energy-matter-tuned.dat' with lines lw 2 dt 1 lc rgb '#332288' title 'matter/tuned', 'slide-to-roll-energy-planck-tuned.dat' with lines lw 2 dt 1 lc rgb '#882255' title 'planck/tuned', 'slide-to-roll-energy-box2d3-tuned.dat' with lines lw 2 dt 1 lc rgb '#D55E00' title 'box2d3/tuned'
set title 'slide-to-roll: the other profiles (dashed)'
plot 'slide-to-roll-energy-exact.dat' with lines lw 1.5 dt 1 lc rgb '#000000' title 'exact (reference)', 'slide-to-roll-energy-home-events.dat' with lines lw 2 dt 3 lc rgb '#0072B2' title 'home/events', 'slide-to-roll-energy-home-soft.dat' with lines lw 2 dt 2 lc rgb '#0072B2' title 'home/soft', 'slide-to-roll-energy-box2d-stock.dat' with lines lw 2 dt 2 lc rgb '#E69F00' title 'box2d/stock', 'slide-to-roll-energy-bullet-stock.dat' with lines lw 2 dt 2 lc rgb '#CC79A7' title 'bullet/stock', 'slide-to-roll-energy-chipmunk-stock.dat' with lines lw 2 dt 2 lc rgb '#009E73' title 'chipmunk/stock', 'slide-to-roll-energy-ode-stock.dat' with lines lw 2 dt 2 lc rgb '#661100' title 'ode/stock', 'slide-to-roll-energy-rapier-stock.dat' with lines lw 2 dt 2 lc rgb '#999933' title 'rapier/stock', 'slide-to-roll-energy-matter-stock.dat' with lines lw 2 dt 2 lc rgb '#332288' title 'matter/stock', 'slide-to-roll-energy-planck-stock.dat' with lines lw 2 dt 2 lc rgb '#882255' title 'planck/stock', 'slide-to-roll-energy-box2d3-stock.dat' with lines lw 2 dt 2 lc rgb '#D55E00' title 'box2d3/stock'
unset multiplot
