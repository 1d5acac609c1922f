set terminal pngcairo size 930,380 font 'sans,10'
set termoption noenhanced
set output 'slide-to-roll-picture.png'
set multiplot layout 1,3
set title 'home at t = 1.5 s'
set xlabel 'x (m)'
set xrange [-0.4:10.4]
set ylabel 'y (m)' offset 1,0
set yrange [-0.4000248490202881:4.4]
set key below font ',8' samplen 2
set size ratio -1
set object 1 rect from 0,0 to 10,4 fs empty border rgb '#c03030' lw 2 front
plot 'slide-to-roll-picture-home-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'slide-to-roll-picture-home-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'slide-to-roll-picture-home-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home/events at t = 1.5 s'
plot 'slide-to-roll-picture-home-events-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'slide-to-roll-picture-home-events-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'slide-to-roll-picture-home-events-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home/soft at t = 1.5 s'
plot 'slide-to-roll-picture-home-soft-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'slide-to-roll-picture-home-soft-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'slide-to-roll-picture-home-soft-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
unset multiplot
