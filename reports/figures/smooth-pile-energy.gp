set terminal pngcairo size 900,740 font 'sans,10'
set termoption noenhanced
set output 'smooth-pile-energy.png'
set xlabel 'time (s)'
set ylabel 'E / E0 (log scale)'
set logscale y
set yrange [1e-4<*:*<1e4]
set grid
set key outside right top font ',9'
set lmargin at screen 0.09
set rmargin at screen 0.70
set multiplot layout 2,1
set title 'Energy over time, smooth-pile: each engine''s first profile'
plot 'smooth-pile-energy-home-seed.dat' with lines lw 2 lc rgb '#777777' dt 1 title 'home-seed (diverged at 1.97 s)', 'smooth-pile-energy-home.dat' with lines lw 2 lc rgb '#0072B2' dt 1 title 'home', 'smooth-pile-energy-exact.dat' with lines lw 2 lc rgb '#000000' dt 1 title 'exact', 'smooth-pile-energy-box2d-tuned.dat' with lines lw 2 lc rgb '#E69F00' dt 1 title 'box2d/tuned', 'smooth-pile-energy-bullet-tuned.dat' with lines lw 2 lc rgb '#CC79A7' dt 1 title 'bullet/tuned', 'smooth-pile-energy-chipmunk-tuned.dat' with lines lw 2 lc rgb '#009E73' dt 1 title 'chipmunk/tuned', 'smooth-pile-energy-lammps-hooke.dat' with lines lw 2 lc rgb '#56B4E9' dt 1 title 'lammps/hooke', 'smooth-pile-energy-ode-tuned.dat' with lines lw 2 lc rgb '#661100' dt 1 title 'ode/tuned', 'smooth-pile-energy-rapier-tuned.dat' with lines lw 2 lc rgb '#999933' dt 1 title 'rapier/tuned', 'smooth-pile-energy-matter-tuned.dat' with lines lw 2 lc rgb '#332288' dt 1 title 'matter/tuned', 'smooth-pile-energy-planck-tuned.dat' with lines lw 2 lc rgb '#882255' dt 1 title 'planck/tuned', 'smooth-pile-energy-box2d3-tuned.dat' with lines lw 2 lc rgb '#D55E00' dt 1 title 'box2d3/tuned'
set title 'smooth-pile: the other profiles (dashed)'
plot 'smooth-pile-energy-exact.dat' with lines lw 1.5 lc rgb '#000000' dt 1 title 'exact (reference)', 'smooth-pile-energy-home-events.dat' with lines lw 2 lc rgb '#0072B2' dt 3 title 'home/events', 'smooth-pile-energy-home-soft.dat' with lines lw 2 lc rgb '#0072B2' dt 2 title 'home/soft', 'smooth-pile-energy-box2d-stock.dat' with lines lw 2 lc rgb '#E69F00' dt 2 title 'box2d/stock', 'smooth-pile-energy-bullet-stock.dat' with lines lw 2 lc rgb '#CC79A7' dt 2 title 'bullet/stock', 'smooth-pile-energy-chipmunk-stock.dat' with lines lw 2 lc rgb '#009E73' dt 2 title 'chipmunk/stock', 'smooth-pile-energy-lammps-hertz.dat' with lines lw 2 lc rgb '#56B4E9' dt 2 title 'lammps/hertz', 'smooth-pile-energy-ode-stock.dat' with lines lw 2 lc rgb '#661100' dt 2 title 'ode/stock', 'smooth-pile-energy-rapier-stock.dat' with lines lw 2 lc rgb '#999933' dt 2 title 'rapier/stock', 'smooth-pile-energy-matter-stock.dat' with lines lw 2 lc rgb '#332288' dt 2 title 'matter/stock', 'smooth-pile-energy-planck-stock.dat' with lines lw 2 lc rgb '#882255' dt 2 title 'planck/stock', 'smooth-pile-energy-box2d3-stock.dat' with lines lw 2 lc rgb '#D55E00' dt 2 title 'box2d3/stock'
unset multiplot
