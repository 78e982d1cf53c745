set terminal pngcairo size 900,600 font 'DejaVu Sans,10' noenhanced
if (!exists('out')) out = "pareto_render_ggx.png"
set output out
set datafile separator ','
set key outside right top box opaque
set grid xtics ytics lc rgb '#dddddd'
set border lw 1
set title "GGX: median min. validation MSE against rendering cost (ns per fragment) (labels: layers x width)"
set xlabel "rendering cost (ns per fragment)"
set ylabel "median min. validation MSE"
set logscale x
set logscale y
set format y '%.0e'
plot "pareto_render_ggx.csv" skip 1 using 2:(strcol(1) eq "all architectures" ? $3 : NaN) with points pt 7 ps 1.0 lc rgb "#1f77b4" title "all architectures", \
     "pareto_render_ggx.csv" skip 1 using 2:(strcol(1) eq "all architectures" ? $3 : NaN):4 with labels offset 0.6,0.6 left font ',8' notitle, \
     "pareto_render_ggx.csv" skip 1 using 2:(strcol(1) eq "Pareto-optimal" ? $3 : NaN) with linespoints lw 2 pt 7 ps 0.8 lc rgb "#d62728" title "Pareto-optimal"
unset output
