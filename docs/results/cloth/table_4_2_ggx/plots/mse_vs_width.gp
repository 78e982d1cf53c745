set terminal pngcairo size 800,520 font 'DejaVu Sans,10' noenhanced
if (!exists('out')) out = "mse_vs_width.png"
set output out
set datafile separator ','
set key outside right top box opaque
set grid xtics ytics lc rgb '#dddddd'
set border lw 1
set title "Table 4.2 — GGX metal: median minimum validation MSE by hidden layers and width"
set xlabel "neurons per hidden layer"
set ylabel "median min. validation MSE"
set logscale y
set format y '%.0e'
set xtics 2
plot "mse_vs_width.csv" skip 1 using 2:(strcol(1) eq "2 layers" ? $3 : NaN) with linespoints lw 2 pt 7 ps 0.8 title "2 layers", \
     "mse_vs_width.csv" skip 1 using 2:(strcol(1) eq "4 layers" ? $3 : NaN) with linespoints lw 2 pt 7 ps 0.8 title "4 layers", \
     "mse_vs_width.csv" skip 1 using 2:(strcol(1) eq "6 layers" ? $3 : NaN) with linespoints lw 2 pt 7 ps 0.8 title "6 layers", \
     "mse_vs_width.csv" skip 1 using 2:(strcol(1) eq "8 layers" ? $3 : NaN) with linespoints lw 2 pt 7 ps 0.8 title "8 layers", \
     "mse_vs_width.csv" skip 1 using 2:(strcol(1) eq "10 layers" ? $3 : NaN) with linespoints lw 2 pt 7 ps 0.8 title "10 layers", \
     "mse_vs_width.csv" skip 1 using 2:(strcol(1) eq "12 layers" ? $3 : NaN) with linespoints lw 2 pt 7 ps 0.8 title "12 layers", \
     "mse_vs_width.csv" skip 1 using 2:(strcol(1) eq "thesis (all depths)" ? $3 : NaN) with points pt 7 ps 1.0 lc rgb "#999999" title "thesis (all depths)"
unset output
