set terminal pngcairo size 900,500 font 'sans,10'
set output 'slide-to-roll-energy.png'
set title 'Energy over time, slide-to-roll'
set xlabel 'time (s)'
set ylabel 'E / E0'
set logscale y
set key outside right
set grid
plot 'slide-to-roll-energy-home.dat' with lines lw 2 dt 1 title 'home', 'slide-to-roll-energy-home-soft.dat' with lines lw 2 dt 1 title 'home/soft', 'slide-to-roll-energy-exact.dat' with lines lw 2 dt 1 title 'exact', 'slide-to-roll-energy-box2d-tuned.dat' with lines lw 2 dt 1 title 'box2d/tuned', 'slide-to-roll-energy-box2d-stock.dat' with lines lw 2 dt 1 title 'box2d/stock', 'slide-to-roll-energy-bullet-tuned.dat' with lines lw 2 dt 1 title 'bullet/tuned', 'slide-to-roll-energy-bullet-stock.dat' with lines lw 2 dt 1 title 'bullet/stock', 'slide-to-roll-energy-chipmunk-tuned.dat' with lines lw 2 dt 1 title 'chipmunk/tuned', 'slide-to-roll-energy-chipmunk-stock.dat' with lines lw 2 dt 2 title 'chipmunk/stock', 'slide-to-roll-energy-lammps-hooke.dat' with lines lw 2 dt 2 title 'lammps/hooke', 'slide-to-roll-energy-ode-tuned.dat' with lines lw 2 dt 2 title 'ode/tuned', 'slide-to-roll-energy-ode-stock.dat' with lines lw 2 dt 2 title 'ode/stock', 'slide-to-roll-energy-rapier-tuned.dat' with lines lw 2 dt 2 title 'rapier/tuned', 'slide-to-roll-energy-rapier-stock.dat' with lines lw 2 dt 2 title 'rapier/stock', 'slide-to-roll-energy-matter-tuned.dat' with lines lw 2 dt 2 title 'matter/tuned', 'slide-to-roll-energy-matter-stock.dat' with lines lw 2 dt 2 title 'matter/stock', 'slide-to-roll-energy-planck-tuned.dat' with lines lw 2 dt 3 title 'planck/tuned', 'slide-to-roll-energy-planck-stock.dat' with lines lw 2 dt 3 title 'planck/stock'
