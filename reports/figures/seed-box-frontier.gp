set terminal pngcairo size 1000,480 font 'sans,10'
set output 'seed-box-frontier.png'
set title 'Stability frontier, seed-box: levels passed of 5 (level k: knob x 2^(k-1))'
set style data histogram
set style histogram cluster gap 1
set style fill solid 0.8 border -1
set boxwidth 0.9
set yrange [0:5.5]
set ytics 1
set grid y
set key outside right
set xtics rotate by -30
set ylabel 'levels passed'
plot for [k=2:5] 'seed-box-frontier.dat' using k:xtic(1) title columnheader
