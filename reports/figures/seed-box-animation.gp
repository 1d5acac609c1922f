set terminal gif animate delay 10 optimize size 836,880 font 'sans,10'
set termoption noenhanced
set output 'seed-box-animation.gif'
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 0.0 s'
set xrange [-5.412484:5.724584]
unset xtics
set yrange [-5.598784:5.439184]
unset ytics
unset key
set border lc rgb '#bbbbbb'
set object 1 rect from -5,-5 to 5,5 fs empty border rgb '#c03030' lw 2 back
plot 'seed-box-animation-home-seed.dat' index 0 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#777777' notitle, 'seed-box-animation-home-seed.dat' index 0 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 0.0 s'
plot 'seed-box-animation-home.dat' index 0 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 0 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 0.0 s'
plot 'seed-box-animation-home-events.dat' index 0 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 0 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 0.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 0 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 0 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 0.4 s'
plot 'seed-box-animation-home-seed.dat' index 1 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#777777' notitle, 'seed-box-animation-home-seed.dat' index 1 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 0.4 s'
plot 'seed-box-animation-home.dat' index 1 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 1 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 0.4 s'
plot 'seed-box-animation-home-events.dat' index 1 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 1 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 0.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 1 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 1 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 0.8 s'
plot 'seed-box-animation-home-seed.dat' index 2 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#777777' notitle, 'seed-box-animation-home-seed.dat' index 2 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 0.8 s'
plot 'seed-box-animation-home.dat' index 2 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 2 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 0.8 s'
plot 'seed-box-animation-home-events.dat' index 2 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 2 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 0.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 2 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 2 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 3 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 3 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 1.3 s'
unset label
plot 'seed-box-animation-home.dat' index 3 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 3 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 1.3 s'
plot 'seed-box-animation-home-events.dat' index 3 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 3 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 1.3 s'
plot 'seed-box-animation-box2d-tuned.dat' index 3 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 3 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 4 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 4 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 1.7 s'
unset label
plot 'seed-box-animation-home.dat' index 4 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 4 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 1.7 s'
plot 'seed-box-animation-home-events.dat' index 4 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 4 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 1.7 s'
plot 'seed-box-animation-box2d-tuned.dat' index 4 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 4 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 5 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 5 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 2.1 s'
unset label
plot 'seed-box-animation-home.dat' index 5 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 5 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 2.1 s'
plot 'seed-box-animation-home-events.dat' index 5 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 5 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 2.1 s'
plot 'seed-box-animation-box2d-tuned.dat' index 5 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 5 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 6 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 6 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 2.5 s'
unset label
plot 'seed-box-animation-home.dat' index 6 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 6 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 2.5 s'
plot 'seed-box-animation-home-events.dat' index 6 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 6 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 2.5 s'
plot 'seed-box-animation-box2d-tuned.dat' index 6 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 6 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 7 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 7 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 2.9 s'
unset label
plot 'seed-box-animation-home.dat' index 7 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 7 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 2.9 s'
plot 'seed-box-animation-home-events.dat' index 7 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 7 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 2.9 s'
plot 'seed-box-animation-box2d-tuned.dat' index 7 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 7 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 8 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 8 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 3.4 s'
unset label
plot 'seed-box-animation-home.dat' index 8 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 8 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 3.4 s'
plot 'seed-box-animation-home-events.dat' index 8 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 8 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 3.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 8 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 8 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 9 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 9 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 3.8 s'
unset label
plot 'seed-box-animation-home.dat' index 9 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 9 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 3.8 s'
plot 'seed-box-animation-home-events.dat' index 9 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 9 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 3.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 9 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 9 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 10 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 10 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 4.2 s'
unset label
plot 'seed-box-animation-home.dat' index 10 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 10 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 4.2 s'
plot 'seed-box-animation-home-events.dat' index 10 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 10 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 4.2 s'
plot 'seed-box-animation-box2d-tuned.dat' index 10 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 10 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 11 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 11 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 4.6 s'
unset label
plot 'seed-box-animation-home.dat' index 11 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 11 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 4.6 s'
plot 'seed-box-animation-home-events.dat' index 11 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 11 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 4.6 s'
plot 'seed-box-animation-box2d-tuned.dat' index 11 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 11 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 12 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 12 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 5.0 s'
unset label
plot 'seed-box-animation-home.dat' index 12 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 12 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 5.0 s'
plot 'seed-box-animation-home-events.dat' index 12 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 12 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 5.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 12 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 12 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 13 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 13 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 5.5 s'
unset label
plot 'seed-box-animation-home.dat' index 13 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 13 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 5.5 s'
plot 'seed-box-animation-home-events.dat' index 13 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 13 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 5.5 s'
plot 'seed-box-animation-box2d-tuned.dat' index 13 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 13 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 14 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 14 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 5.9 s'
unset label
plot 'seed-box-animation-home.dat' index 14 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 14 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 5.9 s'
plot 'seed-box-animation-home-events.dat' index 14 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 14 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 5.9 s'
plot 'seed-box-animation-box2d-tuned.dat' index 14 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 14 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 15 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 15 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 6.3 s'
unset label
plot 'seed-box-animation-home.dat' index 15 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 15 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 6.3 s'
plot 'seed-box-animation-home-events.dat' index 15 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 15 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 6.3 s'
plot 'seed-box-animation-box2d-tuned.dat' index 15 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 15 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 16 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 16 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 6.7 s'
unset label
plot 'seed-box-animation-home.dat' index 16 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 16 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 6.7 s'
plot 'seed-box-animation-home-events.dat' index 16 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 16 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 6.7 s'
plot 'seed-box-animation-box2d-tuned.dat' index 16 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 16 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 17 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 17 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 7.1 s'
unset label
plot 'seed-box-animation-home.dat' index 17 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 17 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 7.1 s'
plot 'seed-box-animation-home-events.dat' index 17 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 17 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 7.1 s'
plot 'seed-box-animation-box2d-tuned.dat' index 17 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 17 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 18 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 18 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 7.6 s'
unset label
plot 'seed-box-animation-home.dat' index 18 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 18 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 7.6 s'
plot 'seed-box-animation-home-events.dat' index 18 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 18 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 7.6 s'
plot 'seed-box-animation-box2d-tuned.dat' index 18 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 18 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 19 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 19 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 8.0 s'
unset label
plot 'seed-box-animation-home.dat' index 19 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 19 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 8.0 s'
plot 'seed-box-animation-home-events.dat' index 19 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 19 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 8.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 19 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 19 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 20 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 20 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 8.4 s'
unset label
plot 'seed-box-animation-home.dat' index 20 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 20 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 8.4 s'
plot 'seed-box-animation-home-events.dat' index 20 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 20 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 8.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 20 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 20 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 21 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 21 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 8.8 s'
unset label
plot 'seed-box-animation-home.dat' index 21 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 21 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 8.8 s'
plot 'seed-box-animation-home-events.dat' index 21 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 21 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 8.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 21 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 21 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 22 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 22 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 9.2 s'
unset label
plot 'seed-box-animation-home.dat' index 22 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 22 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 9.2 s'
plot 'seed-box-animation-home-events.dat' index 22 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 22 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 9.2 s'
plot 'seed-box-animation-box2d-tuned.dat' index 22 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 22 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 23 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 23 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 9.7 s'
unset label
plot 'seed-box-animation-home.dat' index 23 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 23 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 9.7 s'
plot 'seed-box-animation-home-events.dat' index 23 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 23 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 9.7 s'
plot 'seed-box-animation-box2d-tuned.dat' index 23 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 23 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 24 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 24 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 10.1 s'
unset label
plot 'seed-box-animation-home.dat' index 24 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 24 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 10.1 s'
plot 'seed-box-animation-home-events.dat' index 24 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 24 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 10.1 s'
plot 'seed-box-animation-box2d-tuned.dat' index 24 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 24 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 25 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 25 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 10.5 s'
unset label
plot 'seed-box-animation-home.dat' index 25 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 25 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 10.5 s'
plot 'seed-box-animation-home-events.dat' index 25 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 25 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 10.5 s'
plot 'seed-box-animation-box2d-tuned.dat' index 25 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 25 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 26 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 26 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 10.9 s'
unset label
plot 'seed-box-animation-home.dat' index 26 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 26 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 10.9 s'
plot 'seed-box-animation-home-events.dat' index 26 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 26 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 10.9 s'
plot 'seed-box-animation-box2d-tuned.dat' index 26 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 26 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 27 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 27 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 11.3 s'
unset label
plot 'seed-box-animation-home.dat' index 27 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 27 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 11.3 s'
plot 'seed-box-animation-home-events.dat' index 27 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 27 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 11.3 s'
plot 'seed-box-animation-box2d-tuned.dat' index 27 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 27 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 28 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 28 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 11.8 s'
unset label
plot 'seed-box-animation-home.dat' index 28 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 28 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 11.8 s'
plot 'seed-box-animation-home-events.dat' index 28 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 28 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 11.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 28 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 28 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 29 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 29 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 12.2 s'
unset label
plot 'seed-box-animation-home.dat' index 29 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 29 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 12.2 s'
plot 'seed-box-animation-home-events.dat' index 29 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 29 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 12.2 s'
plot 'seed-box-animation-box2d-tuned.dat' index 29 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 29 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 30 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 30 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 12.6 s'
unset label
plot 'seed-box-animation-home.dat' index 30 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 30 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 12.6 s'
plot 'seed-box-animation-home-events.dat' index 30 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 30 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 12.6 s'
plot 'seed-box-animation-box2d-tuned.dat' index 30 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 30 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 31 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 31 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 13.0 s'
unset label
plot 'seed-box-animation-home.dat' index 31 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 31 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 13.0 s'
plot 'seed-box-animation-home-events.dat' index 31 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 31 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 13.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 31 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 31 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 32 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 32 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 13.4 s'
unset label
plot 'seed-box-animation-home.dat' index 32 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 32 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 13.4 s'
plot 'seed-box-animation-home-events.dat' index 32 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 32 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 13.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 32 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 32 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 33 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 33 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 13.9 s'
unset label
plot 'seed-box-animation-home.dat' index 33 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 33 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 13.9 s'
plot 'seed-box-animation-home-events.dat' index 33 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 33 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 13.9 s'
plot 'seed-box-animation-box2d-tuned.dat' index 33 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 33 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 34 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 34 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 14.3 s'
unset label
plot 'seed-box-animation-home.dat' index 34 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 34 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 14.3 s'
plot 'seed-box-animation-home-events.dat' index 34 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 34 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 14.3 s'
plot 'seed-box-animation-box2d-tuned.dat' index 34 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 34 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 35 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 35 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 14.7 s'
unset label
plot 'seed-box-animation-home.dat' index 35 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 35 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 14.7 s'
plot 'seed-box-animation-home-events.dat' index 35 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 35 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 14.7 s'
plot 'seed-box-animation-box2d-tuned.dat' index 35 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 35 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 36 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 36 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 15.1 s'
unset label
plot 'seed-box-animation-home.dat' index 36 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 36 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 15.1 s'
plot 'seed-box-animation-home-events.dat' index 36 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 36 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 15.1 s'
plot 'seed-box-animation-box2d-tuned.dat' index 36 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 36 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 37 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 37 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 15.5 s'
unset label
plot 'seed-box-animation-home.dat' index 37 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 37 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 15.5 s'
plot 'seed-box-animation-home-events.dat' index 37 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 37 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 15.5 s'
plot 'seed-box-animation-box2d-tuned.dat' index 37 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 37 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 38 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 38 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 16.0 s'
unset label
plot 'seed-box-animation-home.dat' index 38 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 38 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 16.0 s'
plot 'seed-box-animation-home-events.dat' index 38 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 38 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 16.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 38 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 38 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 39 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 39 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 16.4 s'
unset label
plot 'seed-box-animation-home.dat' index 39 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 39 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 16.4 s'
plot 'seed-box-animation-home-events.dat' index 39 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 39 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 16.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 39 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 39 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 40 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 40 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 16.8 s'
unset label
plot 'seed-box-animation-home.dat' index 40 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 40 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 16.8 s'
plot 'seed-box-animation-home-events.dat' index 40 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 40 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 16.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 40 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 40 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 41 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 41 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 17.2 s'
unset label
plot 'seed-box-animation-home.dat' index 41 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 41 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 17.2 s'
plot 'seed-box-animation-home-events.dat' index 41 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 41 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 17.2 s'
plot 'seed-box-animation-box2d-tuned.dat' index 41 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 41 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 42 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 42 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 17.6 s'
unset label
plot 'seed-box-animation-home.dat' index 42 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 42 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 17.6 s'
plot 'seed-box-animation-home-events.dat' index 42 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 42 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 17.6 s'
plot 'seed-box-animation-box2d-tuned.dat' index 42 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 42 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 43 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 43 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 18.1 s'
unset label
plot 'seed-box-animation-home.dat' index 43 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 43 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 18.1 s'
plot 'seed-box-animation-home-events.dat' index 43 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 43 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 18.1 s'
plot 'seed-box-animation-box2d-tuned.dat' index 43 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 43 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 44 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 44 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 18.5 s'
unset label
plot 'seed-box-animation-home.dat' index 44 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 44 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 18.5 s'
plot 'seed-box-animation-home-events.dat' index 44 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 44 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 18.5 s'
plot 'seed-box-animation-box2d-tuned.dat' index 44 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 44 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 45 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 45 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 18.9 s'
unset label
plot 'seed-box-animation-home.dat' index 45 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 45 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 18.9 s'
plot 'seed-box-animation-home-events.dat' index 45 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 45 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 18.9 s'
plot 'seed-box-animation-box2d-tuned.dat' index 45 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 45 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 46 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 46 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 19.3 s'
unset label
plot 'seed-box-animation-home.dat' index 46 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 46 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 19.3 s'
plot 'seed-box-animation-home-events.dat' index 46 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 46 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 19.3 s'
plot 'seed-box-animation-box2d-tuned.dat' index 46 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 46 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 47 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 47 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 19.7 s'
unset label
plot 'seed-box-animation-home.dat' index 47 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 47 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 19.7 s'
plot 'seed-box-animation-home-events.dat' index 47 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 47 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 19.7 s'
plot 'seed-box-animation-box2d-tuned.dat' index 47 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 47 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 48 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 48 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 20.2 s'
unset label
plot 'seed-box-animation-home.dat' index 48 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 48 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 20.2 s'
plot 'seed-box-animation-home-events.dat' index 48 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 48 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 20.2 s'
plot 'seed-box-animation-box2d-tuned.dat' index 48 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 48 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 49 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 49 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 20.6 s'
unset label
plot 'seed-box-animation-home.dat' index 49 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 49 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 20.6 s'
plot 'seed-box-animation-home-events.dat' index 49 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 49 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 20.6 s'
plot 'seed-box-animation-box2d-tuned.dat' index 49 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 49 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 50 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 50 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 21.0 s'
unset label
plot 'seed-box-animation-home.dat' index 50 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 50 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 21.0 s'
plot 'seed-box-animation-home-events.dat' index 50 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 50 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 21.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 50 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 50 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 51 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 51 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 21.4 s'
unset label
plot 'seed-box-animation-home.dat' index 51 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 51 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 21.4 s'
plot 'seed-box-animation-home-events.dat' index 51 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 51 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 21.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 51 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 51 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 52 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 52 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 21.8 s'
unset label
plot 'seed-box-animation-home.dat' index 52 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 52 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 21.8 s'
plot 'seed-box-animation-home-events.dat' index 52 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 52 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 21.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 52 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 52 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 53 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 53 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 22.3 s'
unset label
plot 'seed-box-animation-home.dat' index 53 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 53 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 22.3 s'
plot 'seed-box-animation-home-events.dat' index 53 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 53 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 22.3 s'
plot 'seed-box-animation-box2d-tuned.dat' index 53 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 53 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 54 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 54 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 22.7 s'
unset label
plot 'seed-box-animation-home.dat' index 54 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 54 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 22.7 s'
plot 'seed-box-animation-home-events.dat' index 54 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 54 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 22.7 s'
plot 'seed-box-animation-box2d-tuned.dat' index 54 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 54 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 55 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 55 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 23.1 s'
unset label
plot 'seed-box-animation-home.dat' index 55 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 55 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 23.1 s'
plot 'seed-box-animation-home-events.dat' index 55 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 55 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 23.1 s'
plot 'seed-box-animation-box2d-tuned.dat' index 55 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 55 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 56 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 56 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 23.5 s'
unset label
plot 'seed-box-animation-home.dat' index 56 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 56 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 23.5 s'
plot 'seed-box-animation-home-events.dat' index 56 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 56 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 23.5 s'
plot 'seed-box-animation-box2d-tuned.dat' index 56 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 56 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 57 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 57 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 23.9 s'
unset label
plot 'seed-box-animation-home.dat' index 57 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 57 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 23.9 s'
plot 'seed-box-animation-home-events.dat' index 57 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 57 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 23.9 s'
plot 'seed-box-animation-box2d-tuned.dat' index 57 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 57 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 58 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 58 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 24.4 s'
unset label
plot 'seed-box-animation-home.dat' index 58 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 58 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 24.4 s'
plot 'seed-box-animation-home-events.dat' index 58 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 58 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 24.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 58 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 58 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 59 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 59 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 24.8 s'
unset label
plot 'seed-box-animation-home.dat' index 59 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 59 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 24.8 s'
plot 'seed-box-animation-home-events.dat' index 59 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 59 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 24.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 59 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 59 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 60 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 60 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 25.2 s'
unset label
plot 'seed-box-animation-home.dat' index 60 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 60 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 25.2 s'
plot 'seed-box-animation-home-events.dat' index 60 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 60 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 25.2 s'
plot 'seed-box-animation-box2d-tuned.dat' index 60 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 60 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 61 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 61 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 25.6 s'
unset label
plot 'seed-box-animation-home.dat' index 61 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 61 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 25.6 s'
plot 'seed-box-animation-home-events.dat' index 61 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 61 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 25.6 s'
plot 'seed-box-animation-box2d-tuned.dat' index 61 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 61 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 62 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 62 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 26.0 s'
unset label
plot 'seed-box-animation-home.dat' index 62 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 62 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 26.0 s'
plot 'seed-box-animation-home-events.dat' index 62 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 62 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 26.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 62 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 62 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 63 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 63 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 26.5 s'
unset label
plot 'seed-box-animation-home.dat' index 63 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 63 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 26.5 s'
plot 'seed-box-animation-home-events.dat' index 63 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 63 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 26.5 s'
plot 'seed-box-animation-box2d-tuned.dat' index 63 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 63 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 64 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 64 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 26.9 s'
unset label
plot 'seed-box-animation-home.dat' index 64 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 64 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 26.9 s'
plot 'seed-box-animation-home-events.dat' index 64 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 64 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 26.9 s'
plot 'seed-box-animation-box2d-tuned.dat' index 64 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 64 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 65 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 65 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 27.3 s'
unset label
plot 'seed-box-animation-home.dat' index 65 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 65 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 27.3 s'
plot 'seed-box-animation-home-events.dat' index 65 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 65 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 27.3 s'
plot 'seed-box-animation-box2d-tuned.dat' index 65 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 65 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 66 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 66 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 27.7 s'
unset label
plot 'seed-box-animation-home.dat' index 66 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 66 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 27.7 s'
plot 'seed-box-animation-home-events.dat' index 66 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 66 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 27.7 s'
plot 'seed-box-animation-box2d-tuned.dat' index 66 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 66 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 67 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 67 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 28.1 s'
unset label
plot 'seed-box-animation-home.dat' index 67 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 67 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 28.1 s'
plot 'seed-box-animation-home-events.dat' index 67 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 67 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 28.1 s'
plot 'seed-box-animation-box2d-tuned.dat' index 67 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 67 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 68 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 68 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 28.6 s'
unset label
plot 'seed-box-animation-home.dat' index 68 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 68 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 28.6 s'
plot 'seed-box-animation-home-events.dat' index 68 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 68 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 28.6 s'
plot 'seed-box-animation-box2d-tuned.dat' index 68 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 68 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 69 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 69 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 29.0 s'
unset label
plot 'seed-box-animation-home.dat' index 69 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 69 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 29.0 s'
plot 'seed-box-animation-home-events.dat' index 69 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 69 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 29.0 s'
plot 'seed-box-animation-box2d-tuned.dat' index 69 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 69 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 70 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 70 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 29.4 s'
unset label
plot 'seed-box-animation-home.dat' index 70 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 70 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 29.4 s'
plot 'seed-box-animation-home-events.dat' index 70 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 70 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 29.4 s'
plot 'seed-box-animation-box2d-tuned.dat' index 70 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 70 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
set multiplot
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.9568181818181818
set bmargin at screen 0.5068181818181818
set title 'home-seed   t = 1.14 s, its last frame'
set label 1 'diverged at t = 1.20 s' at graph 0.5, graph 0.5 center front font ',13'
plot 'seed-box-animation-home-seed.dat' index 71 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#bbbbbb' notitle, 'seed-box-animation-home-seed.dat' index 71 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'home   t = 29.8 s'
unset label
plot 'seed-box-animation-home.dat' index 71 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home.dat' index 71 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.014354066985645933
set rmargin at screen 0.49282296650717705
set tmargin at screen 0.4636363636363636
set bmargin at screen 0.013636363636363669
set title 'home/events   t = 29.8 s'
plot 'seed-box-animation-home-events.dat' index 71 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#0072B2' notitle, 'seed-box-animation-home-events.dat' index 71 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
set lmargin at screen 0.507177033492823
set rmargin at screen 0.9856459330143541
set title 'box2d/tuned   t = 29.8 s'
plot 'seed-box-animation-box2d-tuned.dat' index 71 using 1:2:($3 * 35.91609569053543 / 3) with points pt 7 ps variable lc rgb '#E69F00' notitle, 'seed-box-animation-box2d-tuned.dat' index 71 using 1:2:($3 * 35.91609569053543 / 3) with points pt 6 ps variable lc rgb '#404040' notitle
unset multiplot
