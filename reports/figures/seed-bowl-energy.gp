set terminal pngcairo size 900,740 font 'sans,10'
set termoption noenhanced
set output 'seed-bowl-energy.png'
set multiplot layout 2,1
set lmargin at screen 0.09
set rmargin at screen 0.7
set title 'Energy over time, seed-bowl: each engine''s first profile'
set logscale y
set xlabel 'time (s)'
set ylabel 'E / E0 (log scale)'
set yrange [0.0001<*:*<10000]
set grid
set key outside right top font ',9'
plot 'seed-bowl-energy-home-seed.dat' with lines lw 2 dt 1 lc rgb '#777777' title 'home-seed', 'seed-bowl-energy-home.dat' with lines lw 2 dt 1 lc rgb '#0072B2' title 'home', 'seed-bowl-energy-exact.dat' with lines lw 2 dt 1 lc rgb '#000000' title 'exact', 'seed-bowl-energy-box2d-tuned.dat' with lines lw 2 dt 1 lc rgb '#E69F00' title 'box2d/tuned', 'seed-bowl-energy-bullet-tuned.dat' with lines lw 2 dt 1 lc rgb '#CC79A7' title 'bullet/tuned (diverged at 21 s)', 'seed-bowl-energy-chipmunk-tuned.dat' with lines lw 2 dt 1 lc rgb '#009E73' title 'chipmunk/tuned', 'seed-bowl-energy-ode-tuned.dat' with lines lw 2 dt 1 lc rgb '#661100' title 'ode/tuned', 'seed-bowl-energy-rapier-tuned.dat' with lines lw 2 dt 1 lc rgb '#999933' title 'rapier/tuned', 'seed-bowl-energy-matter-tuned.dat' with lines lw 2 dt 1 lc rgb '#332288' title 'matter/tuned', 'seed-bowl-energy-planck-tuned.dat' with lines lw 2 dt 1 lc rgb '#882255' title 'planck/tuned', 'seed-bowl-energy-box2d3-tuned.dat' with lines lw 2 dt 1 lc rgb '#D55E00' title 'box2d3/tuned'
set title 'seed-bowl: the other profiles (dashed)'
plot 'seed-bowl-energy-exact.dat' with lines lw 1.5 dt 1 lc rgb '#000000' title 'exact (reference)', 'seed-bowl-energy-home-events.dat' with lines lw 2 dt 3 lc rgb '#0072B2' title 'home/events', 'seed-bowl-energy-home-soft.dat' with lines lw 2 dt 2 lc rgb '#0072B2' title 'home/soft', 'seed-bowl-energy-box2d-stock.dat' with lines lw 2 dt 2 lc rgb '#E69F00' title 'box2d/stock', 'seed-bowl-energy-bullet-stock.dat' with lines lw 2 dt 2 lc rgb '#CC79A7' title 'bullet/stock', 'seed-bowl-energy-chipmunk-stock.dat' with lines lw 2 dt 2 lc rgb '#009E73' title 'chipmunk/stock', 'seed-bowl-energy-ode-stock.dat' with lines lw 2 dt 2 lc rgb '#661100' title 'ode/stock', 'seed-bowl-energy-rapier-stock.dat' with lines lw 2 dt 2 lc rgb '#999933' title 'rapier/stock', 'seed-bowl-energy-matter-stock.dat' with lines lw 2 dt 2 lc rgb '#332288' title 'matter/stock', 'seed-bowl-energy-planck-stock.dat' with lines lw 2 dt 2 lc rgb '#882255' title 'planck/stock', 'seed-bowl-energy-box2d3-stock.dat' with lines lw 2 dt 2 lc rgb '#D55E00' title 'box2d3/stock'
unset multiplot
