set terminal pngcairo size 930,380 font 'sans,10'
set termoption noenhanced
set output 'elastic-gas-picture.png'
set multiplot layout 1,3
set title 'home-seed at t = 2 s'
set xlabel 'x (m)'
set xrange [-21.586568043231203:21.400323878588303]
set ylabel 'y (m)' offset 1,0
set yrange [-21.808420843295806:21.400323878588303]
set key below font ',8' samplen 2
set size ratio -1
set object 1 rect from -19.8,-19.8 to 19.8,19.8 fs empty border rgb '#c03030' lw 2 front
plot 'elastic-gas-picture-home-seed-balls.dat' using 1:2:3 with circles lc rgb '#777777' fs transparent solid 0.45 border lc rgb '#777777' title 'balls', 'elastic-gas-picture-home-seed-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'elastic-gas-picture-home-seed-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'elastic-gas-picture-home-seed-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'elastic-gas-picture-home-seed-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'elastic-gas-picture-home-seed-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home at t = 2 s'
plot 'elastic-gas-picture-home-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'elastic-gas-picture-home-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'elastic-gas-picture-home-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'elastic-gas-picture-home-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'elastic-gas-picture-home-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'elastic-gas-picture-home-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home/events at t = 2 s'
plot 'elastic-gas-picture-home-events-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'elastic-gas-picture-home-events-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'elastic-gas-picture-home-events-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'elastic-gas-picture-home-events-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'elastic-gas-picture-home-events-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'elastic-gas-picture-home-events-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
unset multiplot
