set terminal pngcairo size 900,740 font 'sans,10'
set termoption noenhanced
set output 'rolling-balls-energy.png'
set xlabel 'time (s)'
set ylabel 'E / E0 (log scale)'
set logscale y
set yrange [1e-4<*:*<1e4]
set grid
set key outside right top font ',9'
set lmargin at screen 0.09
set rmargin at screen 0.70
set multiplot layout 2,1
set title 'Energy over time, rolling-balls: each engine''s first profile'
plot 'rolling-balls-energy-home.dat' with lines lw 2 lc rgb '#0072B2' dt 1 title 'home', 'rolling-balls-energy-box2d-tuned.dat' with lines lw 2 lc rgb '#E69F00' dt 1 title 'box2d/tuned', 'rolling-balls-energy-bullet-tuned.dat' with lines lw 2 lc rgb '#CC79A7' dt 1 title 'bullet/tuned', 'rolling-balls-energy-chipmunk-tuned.dat' with lines lw 2 lc rgb '#009E73' dt 1 title 'chipmunk/tuned', 'rolling-balls-energy-lammps-hooke.dat' with lines lw 2 lc rgb '#56B4E9' dt 1 title 'lammps/hooke', 'rolling-balls-energy-ode-tuned.dat' with lines lw 2 lc rgb '#661100' dt 1 title 'ode/tuned', 'rolling-balls-energy-rapier-tuned.dat' with lines lw 2 lc rgb '#999933' dt 1 title 'rapier/tuned', 'rolling-balls-energy-matter-tuned.dat' with lines lw 2 lc rgb '#332288' dt 1 title 'matter/tuned', 'rolling-balls-energy-planck-tuned.dat' with lines lw 2 lc rgb '#882255' dt 1 title 'planck/tuned', 'rolling-balls-energy-box2d3-tuned.dat' with lines lw 2 lc rgb '#D55E00' dt 1 title 'box2d3/tuned'
set title 'rolling-balls: the other profiles (dashed)'
plot 'rolling-balls-energy-home-events.dat' with lines lw 2 lc rgb '#0072B2' dt 3 title 'home/events', 'rolling-balls-energy-home-soft.dat' with lines lw 2 lc rgb '#0072B2' dt 2 title 'home/soft', 'rolling-balls-energy-box2d-stock.dat' with lines lw 2 lc rgb '#E69F00' dt 2 title 'box2d/stock', 'rolling-balls-energy-bullet-stock.dat' with lines lw 2 lc rgb '#CC79A7' dt 2 title 'bullet/stock', 'rolling-balls-energy-chipmunk-stock.dat' with lines lw 2 lc rgb '#009E73' dt 2 title 'chipmunk/stock', 'rolling-balls-energy-ode-stock.dat' with lines lw 2 lc rgb '#661100' dt 2 title 'ode/stock', 'rolling-balls-energy-rapier-stock.dat' with lines lw 2 lc rgb '#999933' dt 2 title 'rapier/stock', 'rolling-balls-energy-matter-stock.dat' with lines lw 2 lc rgb '#332288' dt 2 title 'matter/stock', 'rolling-balls-energy-planck-stock.dat' with lines lw 2 lc rgb '#882255' dt 2 title 'planck/stock', 'rolling-balls-energy-box2d3-stock.dat' with lines lw 2 lc rgb '#D55E00' dt 2 title 'box2d3/stock'
unset multiplot
