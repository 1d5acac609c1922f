set terminal pngcairo size 1350,480 font 'sans,10'
set output 'smooth-pile-picture.png'
set multiplot layout 1,3
set size ratio -1
unset key
unset object
set object 1 rect from -10,0 to 10,3 fs empty border rgb 'red' lw 2
set xrange [-12:12]
set yrange [-2:5]
set title 'home-seed at t = 1.96 s'
plot 'smooth-pile-picture-home-seed-balls.dat' using 1:2:3 with circles fs transparent solid 0.5 lc rgb '#3060c0', 'smooth-pile-picture-home-seed-tracks.dat' index 0:3 using 1:2 with lines lw 1, 'smooth-pile-picture-home-seed-com.dat' using 1:2 with lines lw 2 lc rgb '#ff80c0'
unset object
set object 1 rect from -10,0 to 10,3 fs empty border rgb 'red' lw 2
set xrange [-12:12]
set yrange [-2:5]
set title 'home at t = 4 s'
plot 'smooth-pile-picture-home-balls.dat' using 1:2:3 with circles fs transparent solid 0.5 lc rgb '#3060c0', 'smooth-pile-picture-home-tracks.dat' index 0:3 using 1:2 with lines lw 1, 'smooth-pile-picture-home-com.dat' using 1:2 with lines lw 2 lc rgb '#ff80c0'
unset object
set object 1 rect from -10,0 to 10,3 fs empty border rgb 'red' lw 2
set xrange [-12:12]
set yrange [-2:5]
set title 'home/soft at t = 4 s'
plot 'smooth-pile-picture-home-soft-balls.dat' using 1:2:3 with circles fs transparent solid 0.5 lc rgb '#3060c0', 'smooth-pile-picture-home-soft-tracks.dat' index 0:3 using 1:2 with lines lw 1, 'smooth-pile-picture-home-soft-com.dat' using 1:2 with lines lw 2 lc rgb '#ff80c0'
unset multiplot
