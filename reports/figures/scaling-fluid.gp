set terminal pngcairo size 900,530 font 'sans,10'
set termoption noenhanced
set output 'scaling-fluid.png'
set logscale xy
set grid
set key outside right top font ',9'
set format x '%.0f'
set xlabel 'balls'
set ylabel 'engine ns per ball-step'
set bmargin at screen 0.22641509433962265
set title 'Step cost against ball count, fluid'
set label 1 'Not drawn, diverged: home-seed (1000); bullet/stock (1000); chipmunk/tuned (1000); chipmunk/stock (1000); ode/tuned (1000);' at screen 0.01, screen 0.10566 left font ',8' textcolor rgb '#b03030'
set label 2 '    ode/stock (1000)' at screen 0.01, screen 0.0773585 left font ',8' textcolor rgb '#b03030'
set label 3 'Not drawn, over the time budget: home (10000); home/events (1000, 10000); box2d/tuned (1000); box2d/stock (1000);' at screen 0.01, screen 0.0490566 left font ',8' textcolor rgb '#b03030'
set label 4 '    bullet/tuned (1000)' at screen 0.01, screen 0.0207547 left font ',8' textcolor rgb '#b03030'
plot 'scaling-fluid-home.dat' with linespoints lc rgb '#0072B2' dt 1 pt 7 lw 2 ps 0.8 title 'home', 'scaling-fluid-home-soft.dat' with linespoints lc rgb '#0072B2' dt 2 pt 9 lw 2 ps 0.8 title 'home/soft'
