set terminal pngcairo size 930,380 font 'sans,10'
set termoption noenhanced
set output 'seed-box-picture.png'
set multiplot layout 1,3
set title 'home-seed at t = 1.1 s (diverged)'
set xlabel 'x (m)'
set xrange [-5.428776425984919:6.148187075607904]
set ylabel 'y (m)' offset 1,0
set yrange [-6.105243169327195:5.428776425984919]
set key below font ',8' samplen 2
set size ratio -1
set object 1 rect from -5,-5 to 5,5 fs empty border rgb '#c03030' lw 2 front
plot 'seed-box-picture-home-seed-balls.dat' using 1:2:3 with circles lc rgb '#777777' fs transparent solid 0.45 border lc rgb '#777777' title 'balls', 'seed-box-picture-home-seed-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'seed-box-picture-home-seed-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'seed-box-picture-home-seed-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'seed-box-picture-home-seed-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'seed-box-picture-home-seed-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home at t = 30 s'
plot 'seed-box-picture-home-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'seed-box-picture-home-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'seed-box-picture-home-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'seed-box-picture-home-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'seed-box-picture-home-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'seed-box-picture-home-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home/events at t = 30 s'
plot 'seed-box-picture-home-events-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'seed-box-picture-home-events-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'seed-box-picture-home-events-tracks.dat' index 1 using 1:2 with lines lw 1.2 lc rgb '#009988' title 'track of ball 1', 'seed-box-picture-home-events-tracks.dat' index 2 using 1:2 with lines lw 1.2 lc rgb '#EE7733' title 'track of ball 2', 'seed-box-picture-home-events-tracks.dat' index 3 using 1:2 with lines lw 1.2 lc rgb '#33BBEE' title 'track of ball 3', 'seed-box-picture-home-events-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
unset multiplot
