set terminal pngcairo size 900,485 font 'sans,10'
set termoption noenhanced
set output 'scaling-settled.png'
set bmargin at screen 0.15463917525773196
set title 'Step cost against ball count, settled'
set logscale xy
set xlabel 'balls'
set format x '%.0f'
set ylabel 'engine ns per ball-step'
set grid
set key outside right top font ',9'
set label 1 'Not drawn, over the time budget: home/events (10000)' at screen 0.01, screen 0.02268041237113402 left front font ',8' textcolor rgb '#b03030'
plot 'scaling-settled-home-seed.dat' with linespoints lw 2 dt 1 pt 7 ps 0.8 lc rgb '#777777' title 'home-seed', 'scaling-settled-home.dat' with linespoints lw 2 dt 1 pt 7 ps 0.8 lc rgb '#0072B2' title 'home', 'scaling-settled-home-events.dat' with linespoints lw 2 dt 3 pt 13 ps 0.8 lc rgb '#0072B2' title 'home/events', 'scaling-settled-box2d-tuned.dat' with linespoints lw 2 dt 1 pt 7 ps 0.8 lc rgb '#E69F00' title 'box2d/tuned', 'scaling-settled-box2d-stock.dat' with linespoints lw 2 dt 2 pt 5 ps 0.8 lc rgb '#E69F00' title 'box2d/stock', 'scaling-settled-bullet-tuned.dat' with linespoints lw 2 dt 1 pt 7 ps 0.8 lc rgb '#CC79A7' title 'bullet/tuned', 'scaling-settled-bullet-stock.dat' with linespoints lw 2 dt 2 pt 5 ps 0.8 lc rgb '#CC79A7' title 'bullet/stock', 'scaling-settled-chipmunk-tuned.dat' with linespoints lw 2 dt 1 pt 7 ps 0.8 lc rgb '#009E73' title 'chipmunk/tuned', 'scaling-settled-chipmunk-stock.dat' with linespoints lw 2 dt 2 pt 5 ps 0.8 lc rgb '#009E73' title 'chipmunk/stock', 'scaling-settled-ode-tuned.dat' with linespoints lw 2 dt 1 pt 7 ps 0.8 lc rgb '#661100' title 'ode/tuned', 'scaling-settled-ode-stock.dat' with linespoints lw 2 dt 2 pt 5 ps 0.8 lc rgb '#661100' title 'ode/stock', 'scaling-settled-home-soft.dat' with linespoints lw 2 dt 2 pt 9 ps 0.8 lc rgb '#0072B2' title 'home/soft', 'scaling-settled-home-soft-sleep.dat' with linespoints lw 2 dt 4 pt 11 ps 0.8 lc rgb '#0072B2' title 'home/soft-sleep', 'scaling-settled-box2d-stock-sleep.dat' with linespoints lw 2 dt 4 pt 11 ps 0.8 lc rgb '#E69F00' title 'box2d/stock-sleep'
