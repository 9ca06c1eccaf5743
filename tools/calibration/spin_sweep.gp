# Mz and W against normalised spin, a/b = 1 and 2, every model (doc/theory/calibrated.md).
# Data: creepwork_calibration spin-sweep > spin_sweep.csv
#   gnuplot -e "data='spin_sweep.csv'; out='calibrated_spin.png'" spin_sweep.gp
set datafile separator ','
set terminal pngcairo size 1100,800 font ',10'
set output out
set multiplot layout 2,2
set logscale x
set grid
set key left top
models = "FASTSIM parabolic|FASTSIM elliptic|calibrated|exact 80 x 80"
model(k) = k == 1 ? "FASTSIM parabolic" : k == 2 ? "FASTSIM elliptic" : k == 3 ? "calibrated" : "exact 80 x 80"
styles = "2 3 1 7"
rows(m, ab) = sprintf("< grep '^%s,[^,]*,%s,' %s", ab, m, data)
do for [ab in "1 2"] {
    set title sprintf("a/b = %s, nu = 0.28, pure spin", ab)
    set xlabel "s = phi G c^3 C23 / (mu N)"
    # The models' rows alternate in the file: each curve reads only its
    # model's rows (a filter in the using clause would break the line at
    # every other row).
    set ylabel "-Mz / (mu N c)"
    plot for [k=1:4] rows(model(k), ab) using 2:(-$4) with linespoints lw 2 pt 7 ps 0.6 lc word(styles, k)+0 title model(k)
    set ylabel "W / (mu N)"
    plot for [k=1:4] rows(model(k), ab) using 2:5 with linespoints lw 2 pt 7 ps 0.6 lc word(styles, k)+0 title model(k)
}
unset multiplot
