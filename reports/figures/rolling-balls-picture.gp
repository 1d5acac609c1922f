set terminal pngcairo size 930,380 font 'sans,10'
set termoption noenhanced
set output 'rolling-balls-picture.png'
set multiplot layout 1,3
set title 'home at t = 1.5 s'
set xlabel 'x (m)'
set xrange [-2.8000000000000003:72.8]
set ylabel 'y (m)' offset 1,0
set yrange [-2.8000248490202884:6.800000000000001]
set key below font ',8' samplen 2
set size ratio -1
set object 1 rect from 0,0 to 70,4 fs empty border rgb '#c03030' lw 2 front
plot 'rolling-balls-picture-home-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'rolling-balls-picture-home-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'rolling-balls-picture-home-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'rolling-balls-picture-home-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'rolling-balls-picture-home-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'rolling-balls-picture-home-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home/events at t = 1.5 s'
plot 'rolling-balls-picture-home-events-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'rolling-balls-picture-home-events-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'rolling-balls-picture-home-events-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'rolling-balls-picture-home-events-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'rolling-balls-picture-home-events-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'rolling-balls-picture-home-events-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home/soft at t = 1.5 s'
plot 'rolling-balls-picture-home-soft-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'rolling-balls-picture-home-soft-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'rolling-balls-picture-home-soft-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'rolling-balls-picture-home-soft-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'rolling-balls-picture-home-soft-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'rolling-balls-picture-home-soft-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
unset multiplot
