set terminal pngcairo size 900,480 font 'sans,10'
set output 'rough-pile-picture.png'
set multiplot layout 1,2
set size ratio -1
unset key
unset object
set object 1 rect from -10,0 to 10,3 fs empty border rgb 'red' lw 2
set xrange [-12:12]
set yrange [-2:5]
set title 'home at t = 4 s'
plot 'rough-pile-picture-home-balls.dat' using 1:2:3 with circles fs transparent solid 0.5 lc rgb '#3060c0', 'rough-pile-picture-home-tracks.dat' index 0:3 using 1:2 with lines lw 1, 'rough-pile-picture-home-com.dat' using 1:2 with lines lw 2 lc rgb '#ff80c0'
unset object
set object 1 rect from -10,0 to 10,3 fs empty border rgb 'red' lw 2
set xrange [-12:12]
set yrange [-2:5]
set title 'home/soft at t = 4 s'
plot 'rough-pile-picture-home-soft-balls.dat' using 1:2:3 with circles fs transparent solid 0.5 lc rgb '#3060c0', 'rough-pile-picture-home-soft-tracks.dat' index 0:3 using 1:2 with lines lw 1, 'rough-pile-picture-home-soft-com.dat' using 1:2 with lines lw 2 lc rgb '#ff80c0'
unset multiplot
