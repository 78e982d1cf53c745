set terminal pngcairo size 800,520 font 'DejaVu Sans,10' noenhanced
if (!exists('out')) out = "fig_4_6_depth.png"
set output out
set datafile separator ','
set key outside right top box opaque
set grid xtics ytics lc rgb '#dddddd'
set border lw 1
set title "Figure 4.6 — GGX, width 8, lr 0.00003: validation MSE by depth (median of 3 seeds)"
set xlabel "epoch"
set ylabel "validation MSE"
set logscale x
set logscale y
set format y '%.0e'
plot "fig_4_6_depth.csv" skip 1 using 2:(strcol(1) eq "2 hidden layers" ? $3 : NaN) with lines lw 2 title "2 hidden layers", \
     "fig_4_6_depth.csv" skip 1 using 2:(strcol(1) eq "4 hidden layers" ? $3 : NaN) with lines lw 2 title "4 hidden layers", \
     "fig_4_6_depth.csv" skip 1 using 2:(strcol(1) eq "6 hidden layers" ? $3 : NaN) with lines lw 2 title "6 hidden layers", \
     "fig_4_6_depth.csv" skip 1 using 2:(strcol(1) eq "8 hidden layers" ? $3 : NaN) with lines lw 2 title "8 hidden layers", \
     "fig_4_6_depth.csv" skip 1 using 2:(strcol(1) eq "10 hidden layers" ? $3 : NaN) with lines lw 2 title "10 hidden layers", \
     "fig_4_6_depth.csv" skip 1 using 2:(strcol(1) eq "12 hidden layers" ? $3 : NaN) with lines lw 2 title "12 hidden layers", \
     "fig_4_6_depth.csv" skip 1 using 2:(strcol(1) eq "constant predictor" ? $3 : NaN) with lines lw 2 lc rgb "#888888" title "constant predictor"
unset output
