set terminal pngcairo size 900,500 font 'sans,10'
set output 'smooth-pile-energy.png'
set title 'Energy over time, smooth-pile'
set xlabel 'time (s)'
set ylabel 'E / E0'
set logscale y
set key outside right
set grid
plot 'smooth-pile-energy-home-seed.dat' with lines lw 2 dt 1 title 'home-seed', 'smooth-pile-energy-home.dat' with lines lw 2 dt 1 title 'home', 'smooth-pile-energy-home-soft.dat' with lines lw 2 dt 1 title 'home/soft', 'smooth-pile-energy-exact.dat' with lines lw 2 dt 1 title 'exact', 'smooth-pile-energy-box2d-tuned.dat' with lines lw 2 dt 1 title 'box2d/tuned', 'smooth-pile-energy-box2d-stock.dat' with lines lw 2 dt 1 title 'box2d/stock', 'smooth-pile-energy-bullet-tuned.dat' with lines lw 2 dt 1 title 'bullet/tuned', 'smooth-pile-energy-bullet-stock.dat' with lines lw 2 dt 1 title 'bullet/stock', 'smooth-pile-energy-chipmunk-tuned.dat' with lines lw 2 dt 2 title 'chipmunk/tuned', 'smooth-pile-energy-chipmunk-stock.dat' with lines lw 2 dt 2 title 'chipmunk/stock', 'smooth-pile-energy-lammps-hooke.dat' with lines lw 2 dt 2 title 'lammps/hooke', 'smooth-pile-energy-lammps-hertz.dat' with lines lw 2 dt 2 title 'lammps/hertz', 'smooth-pile-energy-ode-tuned.dat' with lines lw 2 dt 2 title 'ode/tuned', 'smooth-pile-energy-ode-stock.dat' with lines lw 2 dt 2 title 'ode/stock', 'smooth-pile-energy-rapier-tuned.dat' with lines lw 2 dt 2 title 'rapier/tuned', 'smooth-pile-energy-rapier-stock.dat' with lines lw 2 dt 2 title 'rapier/stock', 'smooth-pile-energy-matter-tuned.dat' with lines lw 2 dt 3 title 'matter/tuned', 'smooth-pile-energy-matter-stock.dat' with lines lw 2 dt 3 title 'matter/stock', 'smooth-pile-energy-planck-tuned.dat' with lines lw 2 dt 3 title 'planck/tuned', 'smooth-pile-energy-planck-stock.dat' with lines lw 2 dt 3 title 'planck/stock'
