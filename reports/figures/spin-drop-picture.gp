set terminal pngcairo size 930,380 font 'sans,10'
set termoption noenhanced
set output 'spin-drop-picture.png'
set multiplot layout 1,3
set title 'home at t = 2 s'
set xlabel 'x (m)'
set xrange [-5.4:5.4]
set ylabel 'y (m)' offset 1,0
set yrange [-0.4000248490202881:4.4]
set key below font ',8' samplen 2
set size ratio -1
set object 1 rect from -5,0 to 5,4 fs empty border rgb '#c03030' lw 2 front
plot 'spin-drop-picture-home-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'spin-drop-picture-home-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'spin-drop-picture-home-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home/events at t = 2 s'
plot 'spin-drop-picture-home-events-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'spin-drop-picture-home-events-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'spin-drop-picture-home-events-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
set title 'home/soft at t = 2 s'
plot 'spin-drop-picture-home-soft-balls.dat' using 1:2:3 with circles lc rgb '#0072B2' fs transparent solid 0.45 border lc rgb '#0072B2' title 'balls', 'spin-drop-picture-home-soft-tracks.dat' index 0 using 1:2 with lines lw 1.2 lc rgb '#EE3377' title 'track of ball 0', 'spin-drop-picture-home-soft-com.dat' using 1:2 with lines lw 2 lc rgb '#303030' title 'centre of mass'
unset multiplot
