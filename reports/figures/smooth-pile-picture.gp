set terminal pngcairo size 930,760 font 'sans,10'
set termoption noenhanced
set output 'smooth-pile-picture.png'
set multiplot layout 2,3
set title 'home-seed at t = 1.96 s (diverged)'
set xlabel 'x (m)'
set xrange [-10.819119845247453:10.83017405921187]
set ylabel 'y (m)' offset 1,0
set yrange [-1.3760683219895573:4.149789437451263]
set key below font ',8' samplen 2
set size ratio -1
set object 1 rect from -10,0 to 10,3 fs empty border rgb '#c03030' lw 2 front
plot 'smooth-pile-picture-home-seed-balls.dat' using 1:2:3 with circles lc rgb '#777777' fs transparent solid 0.45 border lc rgb '#777777' title 'balls', 'smooth-pile-picture-home-seed-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'smooth-pile-picture-home-seed-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'smooth-pile-picture-home-seed-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'smooth-pile-picture-home-seed-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'smooth-pile-picture-home-seed-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home at t = 4 s'
plot 'smooth-pile-picture-home-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'smooth-pile-picture-home-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'smooth-pile-picture-home-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'smooth-pile-picture-home-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'smooth-pile-picture-home-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'smooth-pile-picture-home-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home/events at t = 4 s'
plot 'smooth-pile-picture-home-events-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'smooth-pile-picture-home-events-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'smooth-pile-picture-home-events-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'smooth-pile-picture-home-events-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'smooth-pile-picture-home-events-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'smooth-pile-picture-home-events-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home/soft at t = 4 s'
plot 'smooth-pile-picture-home-soft-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'smooth-pile-picture-home-soft-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'smooth-pile-picture-home-soft-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'smooth-pile-picture-home-soft-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'smooth-pile-picture-home-soft-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'smooth-pile-picture-home-soft-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
unset multiplot
