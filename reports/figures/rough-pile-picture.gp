set terminal pngcairo size 930,380 font 'sans,10'
set termoption noenhanced
set output 'rough-pile-picture.png'
set multiplot layout 1,3
set title 'home at t = 4 s'
set xlabel 'x (m)'
set xrange [-10.80089259792393:10.816911646661326]
set ylabel 'y (m)' offset 1,0
set yrange [-0.8258926662649193:3.8006594164661207]
set key below font ',8' samplen 2
set size ratio -1
set object 1 rect from -10,0 to 10,3 fs empty border rgb '#c03030' lw 2 front
plot 'rough-pile-picture-home-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'rough-pile-picture-home-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'rough-pile-picture-home-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'rough-pile-picture-home-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'rough-pile-picture-home-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'rough-pile-picture-home-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home/events at t = 4 s'
plot 'rough-pile-picture-home-events-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'rough-pile-picture-home-events-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'rough-pile-picture-home-events-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'rough-pile-picture-home-events-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'rough-pile-picture-home-events-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'rough-pile-picture-home-events-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home/soft at t = 4 s'
plot 'rough-pile-picture-home-soft-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'rough-pile-picture-home-soft-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'rough-pile-picture-home-soft-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'rough-pile-picture-home-soft-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'rough-pile-picture-home-soft-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'rough-pile-picture-home-soft-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
unset multiplot
