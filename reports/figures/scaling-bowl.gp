set terminal pngcairo size 900,500 font 'sans,10'
set termoption noenhanced
set output 'scaling-bowl.png'
set logscale xy
set grid
set key outside right top font ',9'
set format x '%.0f'
set xlabel 'balls'
set ylabel 'engine ns per ball-step'
set bmargin at screen 0.18
set title 'Step cost against ball count, bowl'
set label 1 'Not drawn, over the time budget: home (1000000)' at screen 0.01, screen 0.052 left font ',8' textcolor rgb '#b03030'
set label 2 'Not drawn, refused: more sub-steps than its cap: lammps/hooke (1000, 10000); lammps/hertz (1000, 10000)' at screen 0.01, screen 0.022 left font ',8' textcolor rgb '#b03030'
plot 'scaling-bowl-home-seed.dat' with linespoints lc rgb '#D55E00' dt 1 lw 2 pt 7 ps 0.8 title 'home-seed', 'scaling-bowl-home.dat' with linespoints lc rgb '#0072B2' dt 1 lw 2 pt 7 ps 0.8 title 'home', 'scaling-bowl-home-events.dat' with linespoints lc rgb '#0072B2' dt 3 lw 2 pt 7 ps 0.8 title 'home/events', 'scaling-bowl-exact.dat' with linespoints lc rgb '#000000' dt 1 lw 2 pt 7 ps 0.8 title 'exact', 'scaling-bowl-box2d-tuned.dat' with linespoints lc rgb '#E69F00' dt 1 lw 2 pt 7 ps 0.8 title 'box2d/tuned', 'scaling-bowl-box2d-stock.dat' with linespoints lc rgb '#E69F00' dt 2 lw 2 pt 7 ps 0.8 title 'box2d/stock', 'scaling-bowl-bullet-tuned.dat' with linespoints lc rgb '#CC79A7' dt 1 lw 2 pt 7 ps 0.8 title 'bullet/tuned', 'scaling-bowl-bullet-stock.dat' with linespoints lc rgb '#CC79A7' dt 2 lw 2 pt 7 ps 0.8 title 'bullet/stock', 'scaling-bowl-chipmunk-tuned.dat' with linespoints lc rgb '#009E73' dt 1 lw 2 pt 7 ps 0.8 title 'chipmunk/tuned', 'scaling-bowl-chipmunk-stock.dat' with linespoints lc rgb '#009E73' dt 2 lw 2 pt 7 ps 0.8 title 'chipmunk/stock', 'scaling-bowl-lammps-hooke.dat' with linespoints lc rgb '#56B4E9' dt 1 lw 2 pt 7 ps 0.8 title 'lammps/hooke', 'scaling-bowl-lammps-hertz.dat' with linespoints lc rgb '#56B4E9' dt 2 lw 2 pt 7 ps 0.8 title 'lammps/hertz', 'scaling-bowl-ode-tuned.dat' with linespoints lc rgb '#AA4499' dt 1 lw 2 pt 7 ps 0.8 title 'ode/tuned', 'scaling-bowl-ode-stock.dat' with linespoints lc rgb '#AA4499' dt 2 lw 2 pt 7 ps 0.8 title 'ode/stock', 'scaling-bowl-rapier-tuned.dat' with linespoints lc rgb '#999933' dt 1 lw 2 pt 7 ps 0.8 title 'rapier/tuned', 'scaling-bowl-rapier-stock.dat' with linespoints lc rgb '#999933' dt 2 lw 2 pt 7 ps 0.8 title 'rapier/stock', 'scaling-bowl-matter-tuned.dat' with linespoints lc rgb '#332288' dt 1 lw 2 pt 7 ps 0.8 title 'matter/tuned', 'scaling-bowl-matter-stock.dat' with linespoints lc rgb '#332288' dt 2 lw 2 pt 7 ps 0.8 title 'matter/stock', 'scaling-bowl-planck-tuned.dat' with linespoints lc rgb '#882255' dt 1 lw 2 pt 7 ps 0.8 title 'planck/tuned', 'scaling-bowl-planck-stock.dat' with linespoints lc rgb '#882255' dt 2 lw 2 pt 7 ps 0.8 title 'planck/stock'
