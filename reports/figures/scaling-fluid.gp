set terminal pngcairo size 900,530 font 'sans,10'
set termoption noenhanced
set output 'scaling-fluid.png'
set bmargin at screen 0.22641509433962265
set title 'Step cost against ball count, fluid'
set logscale xy
set xlabel 'balls'
set format x '%.0f'
set ylabel 'engine ns per ball-step'
set grid
set key outside right top font ',9'
set label 1 'Not drawn, diverged: home-seed (1000); bullet/stock (1000); chipmunk/tuned (1000); chipmunk/stock (1000); ode/tuned (1000);' at screen 0.01, screen 0.10566037735849057 left front font ',8' textcolor rgb '#b03030'
set label 2 '    ode/stock (1000)' at screen 0.01, screen 0.07735849056603773 left front font ',8' textcolor rgb '#b03030'
set label 3 'Not drawn, over the time budget: home (10000); home/events (1000, 10000); box2d/tuned (1000); box2d/stock (1000);' at screen 0.01, screen 0.04905660377358491 left front font ',8' textcolor rgb '#b03030'
set label 4 '    bullet/tuned (1000)' at screen 0.01, screen 0.020754716981132074 left front font ',8' textcolor rgb '#b03030'
plot 'scaling-fluid-home.dat' with linespoints lw 2 dt 1 pt 7 ps 0.8 lc rgb '#0072B2' title 'home', 'scaling-fluid-home-soft.dat' with linespoints lw 2 dt 2 pt 9 ps 0.8 lc rgb '#0072B2' title 'home/soft'
