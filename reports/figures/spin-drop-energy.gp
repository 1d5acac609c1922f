set terminal pngcairo size 900,500 font 'sans,10'
set output 'spin-drop-energy.png'
set title 'Energy over time, spin-drop'
set xlabel 'time (s)'
set ylabel 'E / E0'
set logscale y
set key outside right
set grid
plot 'spin-drop-energy-home.dat' with lines lw 2 dt 1 title 'home', 'spin-drop-energy-home-soft.dat' with lines lw 2 dt 1 title 'home/soft', 'spin-drop-energy-exact.dat' with lines lw 2 dt 1 title 'exact', 'spin-drop-energy-box2d-tuned.dat' with lines lw 2 dt 1 title 'box2d/tuned', 'spin-drop-energy-box2d-stock.dat' with lines lw 2 dt 1 title 'box2d/stock', 'spin-drop-energy-bullet-tuned.dat' with lines lw 2 dt 1 title 'bullet/tuned', 'spin-drop-energy-bullet-stock.dat' with lines lw 2 dt 1 title 'bullet/stock', 'spin-drop-energy-chipmunk-tuned.dat' with lines lw 2 dt 1 title 'chipmunk/tuned', 'spin-drop-energy-chipmunk-stock.dat' with lines lw 2 dt 2 title 'chipmunk/stock', 'spin-drop-energy-lammps-hooke.dat' with lines lw 2 dt 2 title 'lammps/hooke', 'spin-drop-energy-ode-tuned.dat' with lines lw 2 dt 2 title 'ode/tuned', 'spin-drop-energy-ode-stock.dat' with lines lw 2 dt 2 title 'ode/stock', 'spin-drop-energy-rapier-tuned.dat' with lines lw 2 dt 2 title 'rapier/tuned', 'spin-drop-energy-rapier-stock.dat' with lines lw 2 dt 2 title 'rapier/stock', 'spin-drop-energy-matter-tuned.dat' with lines lw 2 dt 2 title 'matter/tuned', 'spin-drop-energy-matter-stock.dat' with lines lw 2 dt 2 title 'matter/stock', 'spin-drop-energy-planck-tuned.dat' with lines lw 2 dt 3 title 'planck/tuned', 'spin-drop-energy-planck-stock.dat' with lines lw 2 dt 3 title 'planck/stock'
