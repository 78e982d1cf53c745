set terminal pngcairo size 800,520 font 'DejaVu Sans,10' noenhanced
if (!exists('out')) out = "fig_4_7_width.png"
set output out
set datafile separator ','
set key outside right top box opaque
set grid xtics ytics lc rgb '#dddddd'
set border lw 1
set title "Figure 4.7 — GGX, 8 hidden layers, lr 0.00003: validation MSE by width (median of 3 seeds)"
set xlabel "epoch"
set ylabel "validation MSE"
set logscale x
set logscale y
set format y '%.0e'
plot "fig_4_7_width.csv" skip 1 using 2:(strcol(1) eq "width 2" ? $3 : NaN) with lines lw 2 title "width 2", \
     "fig_4_7_width.csv" skip 1 using 2:(strcol(1) eq "width 4" ? $3 : NaN) with lines lw 2 title "width 4", \
     "fig_4_7_width.csv" skip 1 using 2:(strcol(1) eq "width 6" ? $3 : NaN) with lines lw 2 title "width 6", \
     "fig_4_7_width.csv" skip 1 using 2:(strcol(1) eq "width 8" ? $3 : NaN) with lines lw 2 title "width 8", \
     "fig_4_7_width.csv" skip 1 using 2:(strcol(1) eq "width 10" ? $3 : NaN) with lines lw 2 title "width 10", \
     "fig_4_7_width.csv" skip 1 using 2:(strcol(1) eq "width 12" ? $3 : NaN) with lines lw 2 title "width 12", \
     "fig_4_7_width.csv" skip 1 using 2:(strcol(1) eq "constant predictor" ? $3 : NaN) with lines lw 2 lc rgb "#888888" title "constant predictor"
unset output
