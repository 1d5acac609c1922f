set terminal pngcairo size 1000,480 font 'sans,10'
set output 'seed-box-frontier.png'
set title 'Stability frontier, seed-box: levels passed of 5 (level k: knob x 2^(k-1))'
set xtics rotate by -30
set ylabel 'levels passed'
set yrange [0:5.5]
set ytics 1
set grid y
set key outside right
set style histogram cluster gap 1
set style fill solid 0.8 border -1
set boxwidth 0.9
plot 'seed-box-frontier.dat' using 2:xtic(1) with histograms title columnheader, 'seed-box-frontier.dat' using 3:xtic(1) with histograms title columnheader, 'seed-box-frontier.dat' using 4:xtic(1) with histograms title columnheader, 'seed-box-frontier.dat' using 5:xtic(1) with histograms title columnheader
