set terminal pngcairo size 900,480 font 'sans,10'
set output 'slide-to-roll-picture.png'
set multiplot layout 1,2
set size ratio -1
unset key
unset object
set object 1 rect from 0,0 to 10,4 fs empty border rgb 'red' lw 2
set xrange [-1:11]
set yrange [-1:5]
set title 'home at t = 1.5 s'
plot 'slide-to-roll-picture-home-balls.dat' using 1:2:3 with circles fs transparent solid 0.5 lc rgb '#3060c0', 'slide-to-roll-picture-home-tracks.dat' index 0:3 using 1:2 with lines lw 1, 'slide-to-roll-picture-home-com.dat' using 1:2 with lines lw 2 lc rgb '#ff80c0'
unset object
set object 1 rect from 0,0 to 10,4 fs empty border rgb 'red' lw 2
set xrange [-1:11]
set yrange [-1:5]
set title 'home/soft at t = 1.5 s'
plot 'slide-to-roll-picture-home-soft-balls.dat' using 1:2:3 with circles fs transparent solid 0.5 lc rgb '#3060c0', 'slide-to-roll-picture-home-soft-tracks.dat' index 0:3 using 1:2 with lines lw 1, 'slide-to-roll-picture-home-soft-com.dat' using 1:2 with lines lw 2 lc rgb '#ff80c0'
unset multiplot
