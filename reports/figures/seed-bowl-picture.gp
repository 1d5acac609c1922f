set terminal pngcairo size 1350,480 font 'sans,10'
set output 'seed-bowl-picture.png'
set multiplot layout 1,3
set size ratio -1
unset key
unset object
set object 1 rect from -5,-5 to 5,5 fs empty border rgb 'red' lw 2
set xrange [-6:6]
set yrange [-6:6]
set title 'home-seed at t = 30 s'
plot 'seed-bowl-picture-home-seed-balls.dat' using 1:2:3 with circles fs transparent solid 0.5 lc rgb '#3060c0', 'seed-bowl-picture-home-seed-tracks.dat' index 0:3 using 1:2 with lines lw 1, 'seed-bowl-picture-home-seed-com.dat' using 1:2 with lines lw 2 lc rgb '#ff80c0'
unset object
set object 1 rect from -5,-5 to 5,5 fs empty border rgb 'red' lw 2
set xrange [-6:6]
set yrange [-6:6]
set title 'home at t = 30 s'
plot 'seed-bowl-picture-home-balls.dat' using 1:2:3 with circles fs transparent solid 0.5 lc rgb '#3060c0', 'seed-bowl-picture-home-tracks.dat' index 0:3 using 1:2 with lines lw 1, 'seed-bowl-picture-home-com.dat' using 1:2 with lines lw 2 lc rgb '#ff80c0'
unset object
set object 1 rect from -5,-5 to 5,5 fs empty border rgb 'red' lw 2
set xrange [-6:6]
set yrange [-6:6]
set title 'home/soft at t = 30 s'
plot 'seed-bowl-picture-home-soft-balls.dat' using 1:2:3 with circles fs transparent solid 0.5 lc rgb '#3060c0', 'seed-bowl-picture-home-soft-tracks.dat' index 0:3 using 1:2 with lines lw 1, 'seed-bowl-picture-home-soft-com.dat' using 1:2 with lines lw 2 lc rgb '#ff80c0'
unset multiplot
