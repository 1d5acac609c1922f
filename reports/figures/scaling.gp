set terminal pngcairo size 1120,520 font 'sans,10'
set output 'scaling.png'
set multiplot layout 1,2
set logscale xy
set grid
set key top left font ',8'
set xlabel 'balls'
set ylabel 'ns per ball-step'
set title 'Step cost, gas'
plot 'scaling-gas-home-seed.dat' with linespoints lc 1 dt 1 lw 2 pt 7 title 'home-seed', 'scaling-gas-home.dat' with linespoints lc 2 dt 1 lw 2 pt 7 title 'home', 'scaling-gas-exact.dat' with linespoints lc 3 dt 1 lw 2 pt 7 title 'exact', 'scaling-gas-box2d-tuned.dat' with linespoints lc 4 dt 1 lw 2 pt 7 title 'box2d/tuned', 'scaling-gas-box2d-stock.dat' with linespoints lc 5 dt 1 lw 2 pt 7 title 'box2d/stock', 'scaling-gas-bullet-tuned.dat' with linespoints lc 6 dt 1 lw 2 pt 7 title 'bullet/tuned', 'scaling-gas-bullet-stock.dat' with linespoints lc 7 dt 1 lw 2 pt 7 title 'bullet/stock', 'scaling-gas-ode-tuned.dat' with linespoints lc 8 dt 1 lw 2 pt 7 title 'ode/tuned', 'scaling-gas-ode-stock.dat' with linespoints lc 1 dt 2 lw 2 pt 7 title 'ode/stock'
set title 'Step cost, bowl'
plot 'scaling-bowl-home-seed.dat' with linespoints lc 1 dt 1 lw 2 pt 7 title 'home-seed', 'scaling-bowl-home.dat' with linespoints lc 2 dt 1 lw 2 pt 7 title 'home', 'scaling-bowl-exact.dat' with linespoints lc 3 dt 1 lw 2 pt 7 title 'exact', 'scaling-bowl-box2d-tuned.dat' with linespoints lc 4 dt 1 lw 2 pt 7 title 'box2d/tuned', 'scaling-bowl-box2d-stock.dat' with linespoints lc 5 dt 1 lw 2 pt 7 title 'box2d/stock', 'scaling-bowl-bullet-tuned.dat' with linespoints lc 6 dt 1 lw 2 pt 7 title 'bullet/tuned', 'scaling-bowl-bullet-stock.dat' with linespoints lc 7 dt 1 lw 2 pt 7 title 'bullet/stock', 'scaling-bowl-ode-tuned.dat' with linespoints lc 8 dt 1 lw 2 pt 7 title 'ode/tuned', 'scaling-bowl-ode-stock.dat' with linespoints lc 1 dt 2 lw 2 pt 7 title 'ode/stock'
unset multiplot
