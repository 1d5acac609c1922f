set terminal gif animate delay 8 optimize size 960,340 font 'sans,9'
set output 'seed-box-animation.gif'
set size ratio -1
unset key
unset xtics
unset ytics
set xrange [-5:5]
set yrange [-5:5]
set object 1 rect from -5,-5 to 5,5 fs empty border rgb 'red' lw 2
set multiplot layout 1,3
set title 'home-seed t = 0.0 s'
plot 'seed-box-animation-home-seed.dat' index 0 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 0.0 s'
plot 'seed-box-animation-home.dat' index 0 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 0.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 0 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 0.4 s'
plot 'seed-box-animation-home-seed.dat' index 1 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 0.4 s'
plot 'seed-box-animation-home.dat' index 1 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 0.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 1 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 0.8 s'
plot 'seed-box-animation-home-seed.dat' index 2 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 0.8 s'
plot 'seed-box-animation-home.dat' index 2 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 0.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 2 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 3 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 1.3 s'
plot 'seed-box-animation-home.dat' index 3 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 1.3 s'
plot 'seed-box-animation-box2d-tuned.dat' index 3 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 4 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 1.7 s'
plot 'seed-box-animation-home.dat' index 4 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 1.7 s'
plot 'seed-box-animation-box2d-tuned.dat' index 4 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 5 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 2.1 s'
plot 'seed-box-animation-home.dat' index 5 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 2.1 s'
plot 'seed-box-animation-box2d-tuned.dat' index 5 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 6 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 2.5 s'
plot 'seed-box-animation-home.dat' index 6 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 2.5 s'
plot 'seed-box-animation-box2d-tuned.dat' index 6 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 7 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 2.9 s'
plot 'seed-box-animation-home.dat' index 7 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 2.9 s'
plot 'seed-box-animation-box2d-tuned.dat' index 7 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 8 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 3.4 s'
plot 'seed-box-animation-home.dat' index 8 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 3.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 8 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 9 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 3.8 s'
plot 'seed-box-animation-home.dat' index 9 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 3.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 9 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 10 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 4.2 s'
plot 'seed-box-animation-home.dat' index 10 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 4.2 s'
plot 'seed-box-animation-box2d-tuned.dat' index 10 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 11 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 4.6 s'
plot 'seed-box-animation-home.dat' index 11 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 4.6 s'
plot 'seed-box-animation-box2d-tuned.dat' index 11 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 12 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 5.0 s'
plot 'seed-box-animation-home.dat' index 12 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 5.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 12 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 13 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 5.5 s'
plot 'seed-box-animation-home.dat' index 13 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 5.5 s'
plot 'seed-box-animation-box2d-tuned.dat' index 13 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 14 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 5.9 s'
plot 'seed-box-animation-home.dat' index 14 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 5.9 s'
plot 'seed-box-animation-box2d-tuned.dat' index 14 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 15 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 6.3 s'
plot 'seed-box-animation-home.dat' index 15 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 6.3 s'
plot 'seed-box-animation-box2d-tuned.dat' index 15 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 16 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 6.7 s'
plot 'seed-box-animation-home.dat' index 16 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 6.7 s'
plot 'seed-box-animation-box2d-tuned.dat' index 16 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 17 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 7.1 s'
plot 'seed-box-animation-home.dat' index 17 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 7.1 s'
plot 'seed-box-animation-box2d-tuned.dat' index 17 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 18 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 7.6 s'
plot 'seed-box-animation-home.dat' index 18 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 7.6 s'
plot 'seed-box-animation-box2d-tuned.dat' index 18 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 19 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 8.0 s'
plot 'seed-box-animation-home.dat' index 19 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 8.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 19 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 20 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 8.4 s'
plot 'seed-box-animation-home.dat' index 20 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 8.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 20 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 21 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 8.8 s'
plot 'seed-box-animation-home.dat' index 21 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 8.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 21 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 22 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 9.2 s'
plot 'seed-box-animation-home.dat' index 22 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 9.2 s'
plot 'seed-box-animation-box2d-tuned.dat' index 22 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 23 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 9.7 s'
plot 'seed-box-animation-home.dat' index 23 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 9.7 s'
plot 'seed-box-animation-box2d-tuned.dat' index 23 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 24 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 10.1 s'
plot 'seed-box-animation-home.dat' index 24 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 10.1 s'
plot 'seed-box-animation-box2d-tuned.dat' index 24 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 25 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 10.5 s'
plot 'seed-box-animation-home.dat' index 25 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 10.5 s'
plot 'seed-box-animation-box2d-tuned.dat' index 25 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 26 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 10.9 s'
plot 'seed-box-animation-home.dat' index 26 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 10.9 s'
plot 'seed-box-animation-box2d-tuned.dat' index 26 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 27 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 11.3 s'
plot 'seed-box-animation-home.dat' index 27 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 11.3 s'
plot 'seed-box-animation-box2d-tuned.dat' index 27 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 28 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 11.8 s'
plot 'seed-box-animation-home.dat' index 28 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 11.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 28 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 29 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 12.2 s'
plot 'seed-box-animation-home.dat' index 29 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 12.2 s'
plot 'seed-box-animation-box2d-tuned.dat' index 29 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 30 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 12.6 s'
plot 'seed-box-animation-home.dat' index 30 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 12.6 s'
plot 'seed-box-animation-box2d-tuned.dat' index 30 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 31 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 13.0 s'
plot 'seed-box-animation-home.dat' index 31 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 13.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 31 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 32 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 13.4 s'
plot 'seed-box-animation-home.dat' index 32 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 13.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 32 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 33 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 13.9 s'
plot 'seed-box-animation-home.dat' index 33 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 13.9 s'
plot 'seed-box-animation-box2d-tuned.dat' index 33 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 34 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 14.3 s'
plot 'seed-box-animation-home.dat' index 34 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 14.3 s'
plot 'seed-box-animation-box2d-tuned.dat' index 34 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 35 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 14.7 s'
plot 'seed-box-animation-home.dat' index 35 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 14.7 s'
plot 'seed-box-animation-box2d-tuned.dat' index 35 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 36 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 15.1 s'
plot 'seed-box-animation-home.dat' index 36 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 15.1 s'
plot 'seed-box-animation-box2d-tuned.dat' index 36 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 37 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 15.5 s'
plot 'seed-box-animation-home.dat' index 37 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 15.5 s'
plot 'seed-box-animation-box2d-tuned.dat' index 37 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 38 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 16.0 s'
plot 'seed-box-animation-home.dat' index 38 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 16.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 38 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 39 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 16.4 s'
plot 'seed-box-animation-home.dat' index 39 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 16.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 39 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 40 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 16.8 s'
plot 'seed-box-animation-home.dat' index 40 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 16.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 40 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 41 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 17.2 s'
plot 'seed-box-animation-home.dat' index 41 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 17.2 s'
plot 'seed-box-animation-box2d-tuned.dat' index 41 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 42 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 17.6 s'
plot 'seed-box-animation-home.dat' index 42 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 17.6 s'
plot 'seed-box-animation-box2d-tuned.dat' index 42 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 43 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 18.1 s'
plot 'seed-box-animation-home.dat' index 43 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 18.1 s'
plot 'seed-box-animation-box2d-tuned.dat' index 43 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 44 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 18.5 s'
plot 'seed-box-animation-home.dat' index 44 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 18.5 s'
plot 'seed-box-animation-box2d-tuned.dat' index 44 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 45 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 18.9 s'
plot 'seed-box-animation-home.dat' index 45 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 18.9 s'
plot 'seed-box-animation-box2d-tuned.dat' index 45 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 46 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 19.3 s'
plot 'seed-box-animation-home.dat' index 46 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 19.3 s'
plot 'seed-box-animation-box2d-tuned.dat' index 46 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 47 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 19.7 s'
plot 'seed-box-animation-home.dat' index 47 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 19.7 s'
plot 'seed-box-animation-box2d-tuned.dat' index 47 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 48 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 20.2 s'
plot 'seed-box-animation-home.dat' index 48 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 20.2 s'
plot 'seed-box-animation-box2d-tuned.dat' index 48 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 49 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 20.6 s'
plot 'seed-box-animation-home.dat' index 49 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 20.6 s'
plot 'seed-box-animation-box2d-tuned.dat' index 49 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 50 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 21.0 s'
plot 'seed-box-animation-home.dat' index 50 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 21.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 50 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 51 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 21.4 s'
plot 'seed-box-animation-home.dat' index 51 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 21.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 51 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 52 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 21.8 s'
plot 'seed-box-animation-home.dat' index 52 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 21.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 52 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 53 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 22.3 s'
plot 'seed-box-animation-home.dat' index 53 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 22.3 s'
plot 'seed-box-animation-box2d-tuned.dat' index 53 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 54 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 22.7 s'
plot 'seed-box-animation-home.dat' index 54 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 22.7 s'
plot 'seed-box-animation-box2d-tuned.dat' index 54 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 55 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 23.1 s'
plot 'seed-box-animation-home.dat' index 55 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 23.1 s'
plot 'seed-box-animation-box2d-tuned.dat' index 55 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 56 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 23.5 s'
plot 'seed-box-animation-home.dat' index 56 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 23.5 s'
plot 'seed-box-animation-box2d-tuned.dat' index 56 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 57 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 23.9 s'
plot 'seed-box-animation-home.dat' index 57 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 23.9 s'
plot 'seed-box-animation-box2d-tuned.dat' index 57 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 58 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 24.4 s'
plot 'seed-box-animation-home.dat' index 58 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 24.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 58 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 59 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 24.8 s'
plot 'seed-box-animation-home.dat' index 59 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 24.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 59 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 60 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 25.2 s'
plot 'seed-box-animation-home.dat' index 60 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 25.2 s'
plot 'seed-box-animation-box2d-tuned.dat' index 60 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 61 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 25.6 s'
plot 'seed-box-animation-home.dat' index 61 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 25.6 s'
plot 'seed-box-animation-box2d-tuned.dat' index 61 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 62 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 26.0 s'
plot 'seed-box-animation-home.dat' index 62 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 26.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 62 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 63 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 26.5 s'
plot 'seed-box-animation-home.dat' index 63 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 26.5 s'
plot 'seed-box-animation-box2d-tuned.dat' index 63 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 64 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 26.9 s'
plot 'seed-box-animation-home.dat' index 64 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 26.9 s'
plot 'seed-box-animation-box2d-tuned.dat' index 64 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 65 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 27.3 s'
plot 'seed-box-animation-home.dat' index 65 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 27.3 s'
plot 'seed-box-animation-box2d-tuned.dat' index 65 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 66 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 27.7 s'
plot 'seed-box-animation-home.dat' index 66 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 27.7 s'
plot 'seed-box-animation-box2d-tuned.dat' index 66 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 67 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 28.1 s'
plot 'seed-box-animation-home.dat' index 67 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 28.1 s'
plot 'seed-box-animation-box2d-tuned.dat' index 67 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 68 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 28.6 s'
plot 'seed-box-animation-home.dat' index 68 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 28.6 s'
plot 'seed-box-animation-box2d-tuned.dat' index 68 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 69 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 29.0 s'
plot 'seed-box-animation-home.dat' index 69 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 29.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 69 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 70 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 29.4 s'
plot 'seed-box-animation-home.dat' index 70 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 29.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 70 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
set multiplot layout 1,3
set title 'home-seed t = 1.1 s (diverged)'
plot 'seed-box-animation-home-seed.dat' index 71 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'home t = 29.8 s'
plot 'seed-box-animation-home.dat' index 71 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
set title 'box2d/tuned t = 29.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 71 using 1:2:3 with circles fs solid 0.6 lc rgb '#3060c0'
unset multiplot
