set terminal pngcairo size 900,740 font 'sans,10'
set termoption noenhanced
set output 'smooth-pile-energy.png'
set multiplot layout 2,1
set lmargin at screen 0.09
set rmargin at screen 0.7
set title 'Energy over time, smooth-pile: each engine''s first profile'
set logscale y
set xlabel 'time (s)'
set ylabel 'E / E0 (log scale)'
set yrange [0.0001<*:*<10000]
set grid
set key outside right top font ',9'
plot 'smooth-pile-energy-home-seed.dat' with lines lw 2 dt 1 lc rgb '#777777' title 'home-seed (diverged at 1.97 s)', 'smooth-pile-energy-home.dat' with lines lw 2 dt 1 lc rgb '#0072B2' title 'home', 'smooth-pile-energy-exact.dat' with lines lw 2 dt 1 lc rgb '#000000' title 'exact', 'smooth-pile-energy-box2d-tuned.dat' with lines lw 2 dt 1 lc rgb '#E69F00' title 'box2d/tuned', 'smooth-pile-energy-bullet-tuned.dat' with lines lw 2 dt 1 lc rgb '#CC79A7' title 'bullet/tuned', 'smooth-pile-energy-chipmunk-tuned.dat' with lines lw 2 dt 1 lc rgb '#009E73' title 'chipmunk/tuned', 'smooth-pile-energy-lammps-hooke.dat' with lines lw 2 dt 1 lc rgb '#56B4E9' title 'lammps/hooke', 'smooth-pile-energy-ode-tuned.dat' with lines lw 2 dt 1 lc rgb '#661100' title 'ode/tuned', 'smooth-pile-energy-rapier-tuned.dat' with lines lw 2 dt 1 lc rgb '#999933' title 'rapier/tuned', 'smooth-pile-energy-matter-tuned.dat' with lines lw 2 dt 1 lc rgb '#332288' title 'matter/tuned', 'smooth-pile-energy-planck-tuned.dat' with lines lw 2 dt 1 lc rgb '#882255' title 'planck/tuned', 'smooth-pile-energy-box2d3-tuned.dat' with lines lw 2 dt 1 lc rgb '#D55E00' title 'box2d3/tuned'
set title 'smooth-pile: the other profiles (dashed)'
plot 'smooth-pile-energy-exact.dat' with lines lw 1.5 dt 1 lc rgb '#000000' title 'exact (reference)', 'smooth-pile-energy-home-events.dat' with lines lw 2 dt 3 lc rgb '#0072B2' title 'home/events', 'smooth-pile-energy-home-soft.dat' with lines lw 2 dt 2 lc rgb '#0072B2' title 'home/soft', 'smooth-pile-energy-box2d-stock.dat' with lines lw 2 dt 2 lc rgb '#E69F00' title 'box2d/stock', 'smooth-pile-energy-bullet-stock.dat' with lines lw 2 dt 2 lc rgb '#CC79A7' title 'bullet/stock', 'smooth-pile-energy-chipmunk-stock.dat' with lines lw 2 dt 2 lc rgb '#009E73' title 'chipmunk/stock', 'smooth-pile-energy-lammps-hertz.dat' with lines lw 2 dt 2 lc rgb '#56B4E9' title 'lammps/hertz', 'smooth-pile-energy-ode-stock.dat' with lines lw 2 dt 2 lc rgb '#661100' title 'ode/stock', 'smooth-pile-energy-rapier-stock.dat' with lines lw 2 dt 2 lc rgb '#999933' title 'rapier/stock', 'smooth-pile-energy-matter-stock.dat' with lines lw 2 dt 2 lc rgb '#332288' title 'matter/stock', 'smooth-pile-energy-planck-stock.dat' with lines lw 2 dt 2 lc rgb '#882255' title 'planck/stock', 'smooth-pile-energy-box2d3-stock.dat' with lines lw 2 dt 2 lc rgb '#D55E00' title 'box2d3/stock'
unset multiplot
