set terminal pngcairo size 900,740 font 'sans,10'
set termoption noenhanced
set output 'spin-drop-energy.png'
set xlabel 'time (s)'
set ylabel 'E / E0 (log scale)'
set logscale y
set yrange [1e-4<*:*<1e4]
set grid
set key outside right top font ',9'
set lmargin at screen 0.09
set rmargin at screen 0.70
set multiplot layout 2,1
set title 'Energy over time, spin-drop: each engine''s first profile'
plot 'spin-drop-energy-home.dat' with lines lw 2 lc rgb '#0072B2' dt 1 title 'home', 'spin-drop-energy-exact.dat' with lines lw 2 lc rgb '#000000' dt 1 title 'exact', 'spin-drop-energy-box2d-tuned.dat' with lines lw 2 lc rgb '#E69F00' dt 1 title 'box2d/tuned', 'spin-drop-energy-bullet-tuned.dat' with lines lw 2 lc rgb '#CC79A7' dt 1 title 'bullet/tuned', 'spin-drop-energy-chipmunk-tuned.dat' with lines lw 2 lc rgb '#009E73' dt 1 title 'chipmunk/tuned', 'spin-drop-energy-lammps-hooke.dat' with lines lw 2 lc rgb '#56B4E9' dt 1 title 'lammps/hooke', 'spin-drop-energy-ode-tuned.dat' with lines lw 2 lc rgb '#661100' dt 1 title 'ode/tuned', 'spin-drop-energy-rapier-tuned.dat' with lines lw 2 lc rgb '#999933' dt 1 title 'rapier/tuned', 'spin-drop-energy-matter-tuned.dat' with lines lw 2 lc rgb '#332288' dt 1 title 'matter/tuned', 'spin-drop-energy-planck-tuned.dat' with lines lw 2 lc rgb '#882255' dt 1 title 'planck/tuned', 'spin-drop-energy-box2d3-tuned.dat' with lines lw 2 lc rgb '#D55E00' dt 1 title 'box2d3/tuned'
set title 'spin-drop: the other profiles (dashed)'
plot 'spin-drop-energy-exact.dat' with lines lw 1.5 lc rgb '#000000' dt 1 title 'exact (reference)', 'spin-drop-energy-home-events.dat' with lines lw 2 lc rgb '#0072B2' dt 3 title 'home/events', 'spin-drop-energy-home-soft.dat' with lines lw 2 lc rgb '#0072B2' dt 2 title 'home/soft', 'spin-drop-energy-box2d-stock.dat' with lines lw 2 lc rgb '#E69F00' dt 2 title 'box2d/stock', 'spin-drop-energy-bullet-stock.dat' with lines lw 2 lc rgb '#CC79A7' dt 2 title 'bullet/stock', 'spin-drop-energy-chipmunk-stock.dat' with lines lw 2 lc rgb '#009E73' dt 2 title 'chipmunk/stock', 'spin-drop-energy-ode-stock.dat' with lines lw 2 lc rgb '#661100' dt 2 title 'ode/stock', 'spin-drop-energy-rapier-stock.dat' with lines lw 2 lc rgb '#999933' dt 2 title 'rapier/stock', 'spin-drop-energy-matter-stock.dat' with lines lw 2 lc rgb '#332288' dt 2 title 'matter/stock', 'spin-drop-energy-planck-stock.dat' with lines lw 2 lc rgb '#882255' dt 2 title 'planck/stock', 'spin-drop-energy-box2d3-stock.dat' with lines lw 2 lc rgb '#D55E00' dt 2 title 'box2d3/stock'
unset multiplot
