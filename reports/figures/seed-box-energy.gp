set terminal pngcairo size 900,500 font 'sans,10'
set output 'seed-box-energy.png'
set title 'Energy over time, seed-box'
set xlabel 'time (s)'
set ylabel 'E / E0'
set logscale y
set key outside right
set grid
plot 'seed-box-energy-home-seed.dat' with lines lw 2 dt 1 title 'home-seed', 'seed-box-energy-home.dat' with lines lw 2 dt 1 title 'home', 'seed-box-energy-exact.dat' with lines lw 2 dt 1 title 'exact', 'seed-box-energy-box2d-tuned.dat' with lines lw 2 dt 1 title 'box2d/tuned', 'seed-box-energy-box2d-stock.dat' with lines lw 2 dt 1 title 'box2d/stock', 'seed-box-energy-bullet-tuned.dat' with lines lw 2 dt 1 title 'bullet/tuned', 'seed-box-energy-bullet-stock.dat' with lines lw 2 dt 1 title 'bullet/stock', 'seed-box-energy-chipmunk-tuned.dat' with lines lw 2 dt 1 title 'chipmunk/tuned', 'seed-box-energy-chipmunk-stock.dat' with lines lw 2 dt 2 title 'chipmunk/stock', 'seed-box-energy-ode-tuned.dat' with lines lw 2 dt 2 title 'ode/tuned', 'seed-box-energy-ode-stock.dat' with lines lw 2 dt 2 title 'ode/stock', 'seed-box-energy-rapier-tuned.dat' with lines lw 2 dt 2 title 'rapier/tuned', 'seed-box-energy-rapier-stock.dat' with lines lw 2 dt 2 title 'rapier/stock', 'seed-box-energy-matter-tuned.dat' with lines lw 2 dt 2 title 'matter/tuned', 'seed-box-energy-matter-stock.dat' with lines lw 2 dt 2 title 'matter/stock', 'seed-box-energy-planck-tuned.dat' with lines lw 2 dt 2 title 'planck/tuned', 'seed-box-energy-planck-stock.dat' with lines lw 2 dt 3 title 'planck/stock'
