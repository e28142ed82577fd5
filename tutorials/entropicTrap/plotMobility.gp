# Mean velocity against chain length, trap array and free solution.
# Usage: gnuplot -e "vFree=<q E/zeta>; stamp='<command, date>'" plotMobility.gp
# Reads mobility.dat (N, left/created, v, se, left/created, v, se, ratio);
# writes mobility.png.

set terminal pngcairo size 1000,700 font "DejaVu Sans,14"
set output "mobility.png"

set logscale x 2
set xrange [7:130]
set xtics (10, 30, 90)
set yrange [0:*]
set tics out nomirror
set grid ytics
set key at graph 0.98, graph 0.62 right top box opaque
set xlabel "beads per chain N (rods = Kuhn lengths: N - 1)"
set ylabel "mean velocity = 40 / <transit time>   (a / time unit)"
set title "Entropic trap array: mean velocity of chains against length\n(error bars: one standard error over the chains of each length)\n".stamp

plot vFree with lines dt 2 lw 2 lc rgb "black" \
        title sprintf("free solution q E / zeta = %.4f", vFree), \
     "mobility.dat" using 1:6:7 with yerrorlines lw 2 pt 6 ps 1.5 \
        lc rgb "#6baed6" title "uniform-depth channel (free solution, same length)", \
     "mobility.dat" using 1:3:4 with yerrorlines lw 2 pt 7 ps 1.5 \
        lc rgb "#d94801" title "trap array (15 batches of uncrossable chains)"
