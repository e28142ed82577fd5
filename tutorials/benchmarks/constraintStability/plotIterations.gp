# Constraint iterations per solve against deltaT (data/stability.dat):
# filled markers, stable runs; open markers, runs stopped by a failed
# solve (iterations up to the stop).
set terminal pngcairo size 1200,560 font "DejaVu Sans,12"
set output "iterations.png"
set multiplot layout 1,2 title "Constraint iterations per solve (mean over the run) against deltaT; open markers: run stopped by a failed solve"
set logscale xy
set format x "%g"
set format y "10^{%L}"
set xlabel "deltaT"
set ylabel "iterations per solve (statistics iterMean)"
set grid lc rgb "#e0e0e0"
set key top left
set yrange [1:30000]
set style line 1 lc rgb "#b2182b" pt 7 ps 1.4 lw 2
set style line 2 lc rgb "#ef8a62" pt 5 ps 1.4 lw 2
set style line 3 lc rgb "#2166ac" pt 9 ps 1.6 lw 2
set style line 4 lc rgb "#1b7837" pt 13 ps 1.6 lw 2
methods = "SHAKE-start SHAKE-end RATTLE newton"
names = "SHAKE\\_start SHAKE\\_end RATTLE newton"
ok(s, m, v) = (strcol(1) eq s && strcol(2) eq m && $3 == 20000 && $5 == 1 ? v : 1/0)
bad(s, m, v) = (strcol(1) eq s && strcol(2) eq m && $3 == 20000 && $5 == 0 && $7 > 0 ? v : 1/0)
do for [s in "trefoil extension"] {
    set title (s eq "trefoil" ? "trefoil, 400 beads, T = 10" : "uniaxial extension, 100 beads, Wi = 34, T = 60")
    set xrange [(s eq "trefoil" ? 0.005 : 0.003):(s eq "trefoil" ? 0.4 : 0.4)]
    plot for [i=1:4] "< sort -k4 -g data/stability.dat" using 4:(ok(s, word(methods, i), $7)) \
            with linespoints ls i title word(names, i), \
         for [i=1:4] "data/stability.dat" using 4:(bad(s, word(methods, i), $7)) \
            with points ls i pt (i == 1 ? 6 : i == 2 ? 4 : i == 3 ? 8 : 12) notitle
}
unset multiplot
