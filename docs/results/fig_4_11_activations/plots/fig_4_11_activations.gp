set terminal pngcairo size 1100,520 font 'DejaVu Sans,10' noenhanced
if (!exists('out')) out = './fig_4_11_activations.png'
if (!exists('data')) data = './fig_4_11_activations.csv'
set output out
set datafile separator ','
set key outside right top box opaque
set grid xtics ytics lc rgb '#dddddd'
set border lw 1
set title 'Figure 4.11 — GGX, 8 x 8, lr 0.00003: validation MSE by activation (median of 3 seeds)'
set xlabel 'epoch'
set ylabel 'validation MSE'
set logscale x
set logscale y
set format y '%.0e'
plot data skip 1 using 2:(strcol(1) eq 'tanh' ? $3 : NaN) with lines lw 2 title 'tanh', \
     data skip 1 using 2:(strcol(1) eq 'sigmoid' ? $3 : NaN) with lines lw 2 title 'sigmoid', \
     data skip 1 using 2:(strcol(1) eq 'ReLU' ? $3 : NaN) with lines lw 2 title 'ReLU', \
     data skip 1 using 2:(strcol(1) eq 'leaky ReLU a=0.05' ? $3 : NaN) with lines lw 2 title 'leaky ReLU a=0.05', \
     data skip 1 using 2:(strcol(1) eq 'leaky ReLU a=0.1' ? $3 : NaN) with lines lw 2 title 'leaky ReLU a=0.1', \
     data skip 1 using 2:(strcol(1) eq 'leaky ReLU a=0.2' ? $3 : NaN) with lines lw 2 title 'leaky ReLU a=0.2', \
     data skip 1 using 2:(strcol(1) eq 'sine (w0 = 1)' ? $3 : NaN) with lines lw 2 dt 2 title 'sine (w0 = 1)', \
     data skip 1 using 2:(strcol(1) eq 'softplus' ? $3 : NaN) with lines lw 2 dt 2 title 'softplus', \
     data skip 1 using 2:(strcol(1) eq 'squareplus' ? $3 : NaN) with lines lw 2 dt 2 title 'squareplus', \
     data skip 1 using 2:(strcol(1) eq 'ELU' ? $3 : NaN) with lines lw 2 dt 2 title 'ELU', \
     data skip 1 using 2:(strcol(1) eq 'GELU (tanh form)' ? $3 : NaN) with lines lw 2 dt 2 title 'GELU (tanh form)', \
     data skip 1 using 2:(strcol(1) eq 'swish' ? $3 : NaN) with lines lw 2 dt 2 title 'swish', \
     data skip 1 using 2:(strcol(1) eq 'exponential' ? $3 : NaN) with lines lw 2 dt 2 title 'exponential (no finite values)', \
     data skip 1 using 2:(strcol(1) eq 'tanh (out tanh)' ? $3 : NaN) with lines lw 2 dt 3 title 'tanh (out tanh)', \
     data skip 1 using 2:(strcol(1) eq 'sigmoid (out sigmoid)' ? $3 : NaN) with lines lw 2 dt 3 title 'sigmoid (out sigmoid)', \
     data skip 1 using 2:(strcol(1) eq 'ReLU (out ReLU)' ? $3 : NaN) with lines lw 2 dt 3 title 'ReLU (out ReLU)', \
     data skip 1 using 2:(strcol(1) eq 'leaky ReLU a=0.1 (out leaky)' ? $3 : NaN) with lines lw 2 dt 3 title 'leaky ReLU a=0.1 (out leaky)', \
     data skip 1 using 2:(strcol(1) eq 'all-zeros output' ? $3 : NaN) with lines lw 2 lc rgb '#888888' title 'all-zeros output', \
     data skip 1 using 2:(strcol(1) eq 'constant predictor' ? $3 : NaN) with lines lw 2 lc rgb '#bbbbbb' title 'constant predictor'
unset output
