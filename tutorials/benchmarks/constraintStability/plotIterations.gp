# Constraint iterations per solve (data/stability.dat and the extension
# runs' statistics): against deltaT for the trefoil and the extension
# (filled markers: stable runs; open markers: runs stopped by a failed solve,
# iterations up to the stop), and against the stretch of the extended chain.
# stamp (summarise): the command and the time of the runs, under the title.
if (!exists("stamp")) stamp = "command and date not given (summarise gives them)"
set terminal pngcairo size 1650,560 font "DejaVu Sans,12"
set output "iterations.png"
set multiplot layout 1,3 title "Constraint iterations per solve (statistics iterMean; maxIterations 20000, newton 50)\n{/*0.8 ".stamp."}"
set logscale xy
set format x "%g"
set format y "10^{%L}"
set grid lc rgb "#e0e0e0"
set yrange [1:30000]
set style line 1 lc rgb "#b2182b" pt 7 ps 1.4 lw 2
set style line 2 lc rgb "#ef8a62" pt 5 ps 1.4 lw 2
set style line 3 lc rgb "#2166ac" pt 9 ps 1.6 lw 2
set style line 4 lc rgb "#1b7837" pt 13 ps 1.6 lw 2
set style line 5 lc rgb "#762a83" pt 3 ps 1.8 lw 2
methods = "SHAKE-start SHAKE-end RATTLE newton exactRods"
names = "SHAKE\\_start SHAKE\\_end RATTLE newton exactRods"
open(i) = (i == 1 ? 6 : i == 2 ? 4 : i == 3 ? 8 : i == 4 ? 12 : 1)
runs(s, m, st) = sprintf("< awk '$1 == \"%s\" && $2 == \"%s\" && $3 == 20000 && $5 == %d && $7 > 0 { print $4, $7 }' data/stability.dat | sort -g", s, m, st)

set xlabel "deltaT"
set ylabel "iterations per solve, mean over the run"
set key center right
do for [s in "trefoil extension"] {
    set title (s eq "trefoil" ? "(a) trefoil, 400 beads, T = 10" : "(b) extension, 100 beads, Wi = 34, T = 60")
    set xrange [0.005:0.6]
    if (s eq "trefoil") { set key center right } else { set key at graph 0.02, graph 0.62 left top Left reverse }
    plot for [i=1:5] runs(s, word(methods, i), 1) using 1:2 \
            with linespoints ls i title word(names, i), \
         for [i=1:5] runs(s, word(methods, i), 0) using 1:2 \
            with points ls i pt open(i) title (i == 1 ? "stopped runs (open)" : "")
}

# (c) extension at deltaT = 0.01: iterations against Ree/L along the run, L = 99 a
set title "(c) extension, deltaT = 0.01: against the stretch"
set xlabel "Ree / L (end-to-end distance over contour length)"
set ylabel "iterations per solve, every 10 steps"
set xrange [0.1:1]
set key at graph 0.98, graph 0.55 right top Right noreverse
stats(m) = sprintf("runs/extension/%s_20000_0.01/postProcessing/polymerCloud/0/statistics.dat", m)
# runs/ is not committed: from the committed data/ alone (summarise after a
# clone) the panel says so instead of failing
if (system("ls runs/extension/*_20000_0.01/postProcessing/polymerCloud/0/statistics.dat 2>/dev/null | wc -l") + 0 > 0) {
    plot for [i=1:5] stats(word(methods, i)) using (sqrt($4)/99):($8 > 0 ? $8 : 1/0) \
            with points ls i ps 0.6 title word(names, i)
} else {
    set label 1 "No runs/extension/*\\_20000\\_0.01 statistics here\n(runs/ is not committed):\nrerun ./Allrun extension" at graph 0.5, graph 0.5 center
    plot NaN notitle
    unset label 1
}
unset multiplot
