set terminal pngcairo size 900,500 font 'sans,10'
set output 'rough-box-energy.png'
set title 'Energy over time, rough-box'
set xlabel 'time (s)'
set ylabel 'E / E0'
set logscale y
set key outside right
set grid
plot 'rough-box-energy-home.dat' with lines lw 2 dt 1 title 'home', 'rough-box-energy-home-soft.dat' with lines lw 2 dt 1 title 'home/soft', 'rough-box-energy-box2d-tuned.dat' with lines lw 2 dt 1 title 'box2d/tuned', 'rough-box-energy-box2d-stock.dat' with lines lw 2 dt 1 title 'box2d/stock', 'rough-box-energy-bullet-tuned.dat' with lines lw 2 dt 1 title 'bullet/tuned', 'rough-box-energy-bullet-stock.dat' with lines lw 2 dt 1 title 'bullet/stock', 'rough-box-energy-chipmunk-tuned.dat' with lines lw 2 dt 1 title 'chipmunk/tuned', 'rough-box-energy-chipmunk-stock.dat' with lines lw 2 dt 1 title 'chipmunk/stock', 'rough-box-energy-lammps-hooke.dat' with lines lw 2 dt 2 title 'lammps/hooke', 'rough-box-energy-lammps-hertz.dat' with lines lw 2 dt 2 title 'lammps/hertz', 'rough-box-energy-ode-tuned.dat' with lines lw 2 dt 2 title 'ode/tuned', 'rough-box-energy-ode-stock.dat' with lines lw 2 dt 2 title 'ode/stock', 'rough-box-energy-rapier-tuned.dat' with lines lw 2 dt 2 title 'rapier/tuned', 'rough-box-energy-rapier-stock.dat' with lines lw 2 dt 2 title 'rapier/stock', 'rough-box-energy-matter-tuned.dat' with lines lw 2 dt 2 title 'matter/tuned', 'rough-box-energy-matter-stock.dat' with lines lw 2 dt 2 title 'matter/stock', 'rough-box-energy-planck-tuned.dat' with lines lw 2 dt 3 title 'planck/tuned', 'rough-box-energy-planck-stock.dat' with lines lw 2 dt 3 title 'planck/stock'
