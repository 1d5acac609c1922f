set terminal pngcairo size 930,760 font 'sans,10'
set termoption noenhanced
set output 'seed-bowl-picture.png'
set multiplot layout 2,3
set title 'home-seed at t = 30 s'
set xlabel 'x (m)'
set xrange [-5.400693393901645:5.400518841007386]
set ylabel 'y (m)' offset 1,0
set yrange [-5.401612779035844:5.400062029962917]
set key below font ',8' samplen 2
set size ratio -1
set object 1 rect from -5,-5 to 5,5 fs empty border rgb '#c03030' lw 2 front
plot 'seed-bowl-picture-home-seed-balls.dat' using 1:2:3 with circles lc rgb '#777777' fs transparent solid 0.45 border lc rgb '#777777' title 'balls', 'seed-bowl-picture-home-seed-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'seed-bowl-picture-home-seed-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'seed-bowl-picture-home-seed-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'seed-bowl-picture-home-seed-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'seed-bowl-picture-home-seed-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home at t = 30 s'
plot 'seed-bowl-picture-home-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'seed-bowl-picture-home-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'seed-bowl-picture-home-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'seed-bowl-picture-home-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'seed-bowl-picture-home-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'seed-bowl-picture-home-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home/events at t = 30 s'
plot 'seed-bowl-picture-home-events-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'seed-bowl-picture-home-events-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'seed-bowl-picture-home-events-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'seed-bowl-picture-home-events-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'seed-bowl-picture-home-events-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'seed-bowl-picture-home-events-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home/soft at t = 30 s'
plot 'seed-bowl-picture-home-soft-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'seed-bowl-picture-home-soft-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'seed-bowl-picture-home-soft-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'seed-bowl-picture-home-soft-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'seed-bowl-picture-home-soft-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'seed-bowl-picture-home-soft-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
unset multiplot
