set terminal pngcairo size 900,500 font 'sans,10'
set output 'seed-bowl-energy.png'
set title 'Energy over time, seed-bowl'
set xlabel 'time (s)'
set ylabel 'E / E0'
set logscale y
set key outside right
set grid
plot 'seed-bowl-energy-home-seed.dat' with lines lw 2 dt 1 title 'home-seed', 'seed-bowl-energy-home.dat' with lines lw 2 dt 1 title 'home', 'seed-bowl-energy-home-soft.dat' with lines lw 2 dt 1 title 'home/soft', 'seed-bowl-energy-exact.dat' with lines lw 2 dt 1 title 'exact', 'seed-bowl-energy-box2d-tuned.dat' with lines lw 2 dt 1 title 'box2d/tuned', 'seed-bowl-energy-box2d-stock.dat' with lines lw 2 dt 1 title 'box2d/stock', 'seed-bowl-energy-bullet-tuned.dat' with lines lw 2 dt 1 title 'bullet/tuned', 'seed-bowl-energy-bullet-stock.dat' with lines lw 2 dt 1 title 'bullet/stock', 'seed-bowl-energy-chipmunk-tuned.dat' with lines lw 2 dt 2 title 'chipmunk/tuned', 'seed-bowl-energy-chipmunk-stock.dat' with lines lw 2 dt 2 title 'chipmunk/stock', 'seed-bowl-energy-ode-tuned.dat' with lines lw 2 dt 2 title 'ode/tuned', 'seed-bowl-energy-ode-stock.dat' with lines lw 2 dt 2 title 'ode/stock', 'seed-bowl-energy-rapier-tuned.dat' with lines lw 2 dt 2 title 'rapier/tuned', 'seed-bowl-energy-rapier-stock.dat' with lines lw 2 dt 2 title 'rapier/stock', 'seed-bowl-energy-matter-tuned.dat' with lines lw 2 dt 2 title 'matter/tuned', 'seed-bowl-energy-matter-stock.dat' with lines lw 2 dt 2 title 'matter/stock', 'seed-bowl-energy-planck-tuned.dat' with lines lw 2 dt 3 title 'planck/tuned', 'seed-bowl-energy-planck-stock.dat' with lines lw 2 dt 3 title 'planck/stock'
