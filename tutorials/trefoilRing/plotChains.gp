# Four snapshots of the closed trefoil ring (the paper's uncut trefoil).
# Usage: gnuplot -c plotChains.gp <time1> <time2> <time3> <time4>
# Reads postProcessing/chains/<time>.xyz ('x y z', one bead a line, in order)
# and writes trefoilRing.png; each file repeats its first bead at the end,
# so the ring is drawn closed.

file(i) = sprintf("postProcessing/chains/%s.xyz", ARGV[i])

# One cube for all panels: the largest extent of any snapshot
R = 0
do for [i=1:ARGC] {
    stats file(i) using 1 nooutput
    R = (abs(STATS_min) > R) ? abs(STATS_min) : R
    R = (abs(STATS_max) > R) ? abs(STATS_max) : R
    stats file(i) using 2 nooutput
    R = (abs(STATS_min) > R) ? abs(STATS_min) : R
    R = (abs(STATS_max) > R) ? abs(STATS_max) : R
    stats file(i) using 3 nooutput
    R = (abs(STATS_min) > R) ? abs(STATS_min) : R
    R = (abs(STATS_max) > R) ? abs(STATS_max) : R
}
R = 5*ceil(1.05*R/5)

set terminal pngcairo size 1400,1400 font "DejaVu Sans,15"
set output "trefoilRing.png"

set xrange [-R:R]
set yrange [-R:R]
set zrange [-R:R]
set view 55, 30, 1.25
set view equal xyz
set xyplane 0
set border 4095 lc rgb "#b0b0b0" lw 1
unset xtics
unset ytics
unset ztics
unset key
unset colorbox
set palette defined (0 "#1f3b99", 0.5 "#2ca25f", 1 "#d95f0e")
set cbrange [0:399]
set margins 0, 0, 0, 0

set multiplot layout 2,2 \
    title sprintf("400-bead ring tied in a trefoil, Brownian motion and rod-rod collisions (box edge %g)", 2*R) \
    font ",18"
do for [i=1:ARGC] {
    set title sprintf("t = %s%s", ARGV[i], i == 1 && ARGV[i] == "0" ? " (closed trefoil)" : "") font ",17" offset 0,-2
    splot file(i) using 1:2:3:0 with lines lw 2 lc palette, \
          ''      using 1:2:3:0 with points pt 7 ps 0.45 lc palette
}
unset multiplot
