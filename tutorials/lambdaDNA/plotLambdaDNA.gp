# lambdaDNA.png: the chains over the flow speed in the mid-depth plane at
# four times; stretch.png: each chain's extension along the flow against its
# position, with the centre line's Weissenberg number.
# Usage: gnuplot -c plotLambdaDNA.gp <tau> <t1> <t2> <t3> <t4>
# Reads postProcessing/picture/{speed,chains}_<t>.dat, extension.dat and
# strainRate.dat (lengths in um, times in s).

tau = real(ARG1)

set terminal pngcairo size 1600,760 font "DejaVu Sans,14"
set output "lambdaDNA.png"

set xrange [-30:30]
set yrange [-10:10]
set size ratio -1
set cbrange [0:3000]
set cblabel "flow speed |U| (um/s)"
set palette defined (0 "#f7fbff", 0.3 "#c6dbef", 0.6 "#6baed6", 1 "#08519c")
unset key
set tics out nomirror
set xlabel "x (um)"
set ylabel "y (um)"

set multiplot layout 2,2 title \
    "lambda-DNA (48.5 kbp, 16 rods of 1.03 um) through a 10:3 contraction at 500 um/s, pimpleFoam + polymerCloud fvOption" \
    font ",16"
do for [i=2:ARGC] {
    set title sprintf("t = %s s", ARGV[i])
    plot sprintf("postProcessing/picture/speed_%s.dat", ARGV[i]) \
            using 1:2:3 with points pt 5 ps 1.6 lc palette, \
         sprintf("postProcessing/picture/chains_%s.dat", ARGV[i]) \
            using 1:2 with lines lw 2 lc rgb "#d94801"
}
unset multiplot

set output "stretch.png"
set terminal pngcairo size 1100,650 font "DejaVu Sans,14"
set size noratio
set autoscale
set xrange [-30:30]
set yrange [0:1]
set y2range [0:*]
set ytics nomirror
set y2tics
set xlabel "chain centre x (um)   (the contraction at x = 0)"
set ylabel "extension along the flow, x span / contour length"
set y2label sprintf("Weissenberg number, centre line dUx/dx x tau (tau = %.2g s)", tau)
set key top left
set title "Each chain at every written time (0.005 s apart); the flow's Wi on the centre line"
plot "postProcessing/picture/extension.dat" using 2:3 with points pt 7 ps 1 lc rgb "#d94801" title "chains", \
     "postProcessing/picture/strainRate.dat" using 1:($2*tau) axes x1y2 with lines lw 2 lc rgb "#08519c" title "Wi (right axis)"
