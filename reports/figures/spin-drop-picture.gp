set terminal pngcairo size 900,480 font 'sans,10'
set output 'spin-drop-picture.png'
set multiplot layout 1,2
set size ratio -1
unset key
unset object
set object 1 rect from -5,0 to 5,4 fs empty border rgb 'red' lw 2
set xrange [-6:6]
set yrange [-1:5]
set title 'home at t = 2 s'
plot 'spin-drop-picture-home-balls.dat' using 1:2:3 with circles fs transparent solid 0.5 lc rgb '#3060c0', 'spin-drop-picture-home-tracks.dat' index 0:3 using 1:2 with lines lw 1, 'spin-drop-picture-home-com.dat' using 1:2 with lines lw 2 lc rgb '#ff80c0'
unset object
set object 1 rect from -5,0 to 5,4 fs empty border rgb 'red' lw 2
set xrange [-6:6]
set yrange [-1:5]
set title 'home/soft at t = 2 s'
plot 'spin-drop-picture-home-soft-balls.dat' using 1:2:3 with circles fs transparent solid 0.5 lc rgb '#3060c0', 'spin-drop-picture-home-soft-tracks.dat' index 0:3 using 1:2 with lines lw 1, 'spin-drop-picture-home-soft-com.dat' using 1:2 with lines lw 2 lc rgb '#ff80c0'
unset multiplot
