set terminal pngcairo size 900,600 font 'DejaVu Sans,10' noenhanced
if (!exists('out')) out = "pareto_unseen_phong.png"
set output out
set datafile separator ','
set key outside right top box opaque
set grid xtics ytics lc rgb '#dddddd'
set border lw 1
set title "Phong: median image MSE on unseen meshes against rendering cost (ns per fragment) (labels: layers x width)"
set xlabel "rendering cost (ns per fragment)"
set ylabel "median image MSE on unseen meshes"
set logscale x
set logscale y
set format y '%.0e'
plot "pareto_unseen_phong.csv" skip 1 using 2:(strcol(1) eq "all architectures" ? $3 : NaN) with points pt 7 ps 1.0 lc rgb "#1f77b4" title "all architectures", \
     "pareto_unseen_phong.csv" skip 1 using 2:(strcol(1) eq "all architectures" ? $3 : NaN):4 with labels offset 0.6,0.6 left font ',8' notitle, \
     "pareto_unseen_phong.csv" skip 1 using 2:(strcol(1) eq "Pareto-optimal" ? $3 : NaN) with linespoints lw 2 pt 7 ps 0.8 lc rgb "#d62728" title "Pareto-optimal"
unset output
