# Chains over the flow speed in the contraction's mid-depth plane, at four
# times. Usage: gnuplot -c plotContraction.gp <t1> <t2> <t3> <t4>
# Reads postProcessing/picture/{speed,chains}_<t>.dat; writes contraction.png.

set terminal pngcairo size 1600,760 font "DejaVu Sans,14"
set output "contraction.png"

set xrange [-30:30]
set yrange [-10:10]
set size ratio -1
set cbrange [0:5]
set cblabel "flow speed |U|"
set palette defined (0 "#f7fbff", 0.3 "#c6dbef", 0.6 "#6baed6", 1 "#08519c")
unset key
set tics out nomirror
set xlabel "x (rod lengths)"
set ylabel "y"

set multiplot layout 2,2 title \
    "Kramers chains (20 beads) carried through a 10:3 contraction: flow solved, walls, outlet" \
    font ",16"
do for [i=1:ARGC] {
    set title sprintf("t = %s", ARGV[i])
    plot sprintf("postProcessing/picture/speed_%s.dat", ARGV[i]) \
            using 1:2:3 with points pt 5 ps 1.6 lc palette, \
         sprintf("postProcessing/picture/chains_%s.dat", ARGV[i]) \
            using 1:2 with lines lw 2 lc rgb "#d94801"
}
unset multiplot
