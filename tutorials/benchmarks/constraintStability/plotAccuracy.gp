# Error of exact equilibrium averages against CPU cost (data/accuracy.dat):
# one curve per method (the points are deltaT = 0.01, 0.02, 0.04, 0.08,
# 0.16 from right to left, labelled for newton and SHAKE end), error bars
# one standard error; the dashed line is about one standard error (errors
# below it are noise). stamp (summarise): the command and the time of the
# runs, under the title.
if (!exists("stamp")) stamp = "command and date not given (summarise gives them)"
set terminal pngcairo size 1200,560 font "DejaVu Sans,12"
set output "accuracyCost.png"
set multiplot layout 1,2 title "Accuracy against cost: 2000 trimers + 300 chains of 20 beads, a = m = zeta = kT = 1\n{/*0.8 ".stamp."}"
set logscale xy
set format x "%g"
set format y "10^{%L}"
set xlabel "CPU seconds of cloud evolution per unit simulated time"
set grid lc rgb "#e0e0e0"
set key top right box opaque
set style line 1 lc rgb "#b2182b" pt 7 ps 1.3 lw 2
set style line 2 lc rgb "#ef8a62" pt 5 ps 1.3 lw 2
set style line 3 lc rgb "#2166ac" pt 9 ps 1.5 lw 2
set style line 4 lc rgb "#1b7837" pt 13 ps 1.5 lw 2
methods = "SHAKE-start SHAKE-end RATTLE newton"
names = "SHAKE\\_start SHAKE\\_end RATTLE newton"
sel(m, v) = (strcol(1) eq m && $8 == 1 ? v : 1/0)
floor = 1e-5
absr(x) = (abs(x) > floor ? abs(x) : floor)

set title "|<cos^2 theta> - 0.32102| (trimers)"
set ylabel "absolute error"
set yrange [1e-4:0.5]
plot for [i=1:4] "data/accuracy.dat" using (sel(word(methods, i), $7)):(absr($3 - 0.32102)):4 \
        with yerrorlines ls i title word(names, i), \
     for [m in "newton SHAKE-end"] "data/accuracy.dat" using (sel(m, $7)):(absr($3 - 0.32102)):(sprintf("%g", $2)) \
        with labels offset 0,-1 font ",9" notitle, \
     abs(1/3.0 - 0.32102) with lines dt 3 lw 1.5 lc rgb "#666666" title "freely jointed 1/3", \
     0.0012 with lines dt 2 lw 1.5 lc rgb "#999999" title "1 standard error"

set title "|<Ree^2> - 19| / 19 (20-bead chains)"
set ylabel "relative error"
set yrange [1e-4:10]
plot for [i=1:4] "data/accuracy.dat" using (sel(word(methods, i), $7)):(absr($5/19 - 1)):($6/19) \
        with yerrorlines ls i title word(names, i), \
     for [m in "newton SHAKE-end"] "data/accuracy.dat" using (sel(m, $7)):(absr($5/19 - 1)):(sprintf("%g", $2)) \
        with labels offset 0,-1 font ",9" notitle, \
     0.025 with lines dt 2 lw 1.5 lc rgb "#999999" title "1 standard error"
unset multiplot
