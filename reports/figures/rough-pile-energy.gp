set terminal pngcairo size 900,500 font 'sans,10'
set output 'rough-pile-energy.png'
set title 'Energy over time, rough-pile'
set xlabel 'time (s)'
set ylabel 'E / E0'
set logscale y
set key outside right
set grid
plot 'rough-pile-energy-home.dat' with lines lw 2 dt 1 title 'home', 'rough-pile-energy-home-soft.dat' with lines lw 2 dt 1 title 'home/soft', 'rough-pile-energy-box2d-tuned.dat' with lines lw 2 dt 1 title 'box2d/tuned', 'rough-pile-energy-box2d-stock.dat' with lines lw 2 dt 1 title 'box2d/stock', 'rough-pile-energy-bullet-tuned.dat' with lines lw 2 dt 1 title 'bullet/tuned', 'rough-pile-energy-bullet-stock.dat' with lines lw 2 dt 1 title 'bullet/stock', 'rough-pile-energy-chipmunk-tuned.dat' with lines lw 2 dt 1 title 'chipmunk/tuned', 'rough-pile-energy-chipmunk-stock.dat' with lines lw 2 dt 1 title 'chipmunk/stock', 'rough-pile-energy-lammps-hooke.dat' with lines lw 2 dt 2 title 'lammps/hooke', 'rough-pile-energy-lammps-hertz.dat' with lines lw 2 dt 2 title 'lammps/hertz', 'rough-pile-energy-ode-tuned.dat' with lines lw 2 dt 2 title 'ode/tuned', 'rough-pile-energy-ode-stock.dat' with lines lw 2 dt 2 title 'ode/stock', 'rough-pile-energy-rapier-tuned.dat' with lines lw 2 dt 2 title 'rapier/tuned', 'rough-pile-energy-rapier-stock.dat' with lines lw 2 dt 2 title 'rapier/stock', 'rough-pile-energy-matter-tuned.dat' with lines lw 2 dt 2 title 'matter/tuned', 'rough-pile-energy-matter-stock.dat' with lines lw 2 dt 2 title 'matter/stock', 'rough-pile-energy-planck-tuned.dat' with lines lw 2 dt 3 title 'planck/tuned', 'rough-pile-energy-planck-stock.dat' with lines lw 2 dt 3 title 'planck/stock'
