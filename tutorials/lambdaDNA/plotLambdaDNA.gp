# lambdaDNA.png: the chains over the flow speed in the mid-depth plane at
# four times; stretch.png: each chain's extension along the flow against its
# position, with the centre line's Weissenberg number, and the extension of
# the chains near the centre line against its Hencky strain, with the
# affine stretch of the equilibrium coil's span.
# Usage: gnuplot -c plotLambdaDNA.gp <tau> <span> <t1> <t2> <t3> <t4>
# Reads postProcessing/picture/{speed,chains}_<t>.dat, extension.dat,
# strainRate.dat and strain.dat (lengths in um, times in s).

tau = real(ARG1)
span = real(ARG2)

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
do for [i=3:ARGC] {
    set title sprintf("t = %s s", ARGV[i])
    plot sprintf("postProcessing/picture/speed_%s.dat", ARGV[i]) \
            using 1:2:3 with points pt 5 ps 1.6 lc palette, \
         sprintf("postProcessing/picture/chains_%s.dat", ARGV[i]) \
            using 1:2 with lines lw 2 lc rgb "#d94801"
}
unset multiplot

set output "stretch.png"
set terminal pngcairo size 1800,720 font "DejaVu Sans,14"
set size noratio
set autoscale
set multiplot layout 1,2 title \
    sprintf("Extension of the chains (measured relaxation time tau = %.3g s; every written time, 0.005 s apart)", tau) \
    font ",16"

set xrange [-30:30]
set yrange [0:1]
set y2range [0.1:1000]
set logscale y2
set ytics nomirror
set y2tics
set xlabel "chain centre x (um)   (the contraction at x = 0)"
set ylabel "extension along the flow, x span / contour length"
set y2label "Weissenberg number, centre line dUx/dx x tau"
set key below
set title "Against position, with the flow's Wi on the centre line"
plot "postProcessing/picture/extension.dat" using 2:3 with points pt 7 ps 1 lc rgb "#d94801" title "chains", \
     "postProcessing/picture/strainRate.dat" using 1:($2*tau) axes x1y2 with lines lw 2 lc rgb "#08519c" title "Wi (right axis)", \
     0.5 axes x1y2 with lines dt 2 lw 2 lc rgb "#08519c" title "Wi = 0.5, onset of stretching (right axis)"

unset logscale y2
unset y2tics
unset y2label
set xrange [0:*]
set key inside top left opaque
unset bmargin
set xlabel "Hencky strain of the centre line since the inlet, ln(U_x/U_{inlet})"
set title "Chains within 2 um of the centre line, against the strain at their centre"
plot "postProcessing/picture/strain.dat" using 1:2 with points pt 7 ps 1 lc rgb "#d94801" title "chains", \
     (x < log(1/span) ? span*exp(x) : 1) with lines lw 2 lc rgb "black" \
        title sprintf("affine: coil span %.2g L times exp(strain)", span)
unset multiplot
