# The trap array in the x-z plane (side view) with the chains projected on
# it, at four times. Usage: gnuplot -c plotEntropicTrap.gp <t1> <t2> <t3> <t4>
# Reads postProcessing/picture/chains_<t>_<type>.dat (type 0-2: N10, N20,
# N40); writes entropicTrap.png.

set terminal pngcairo size 1600,1400 font "DejaVu Sans,14"
set output "entropicTrap.png"

# Channel outline: floor z = 0; wells 8 deep, slits 1 deep
$walls << EOD
0 8
0 0
40 0
40 1

0 8
6 8
6 1
10 1
10 8
16 8
16 1
20 1
20 8
26 8
26 1
30 1
30 8
36 8
36 1
40 1
EOD

set xrange [-0.5:40.5]
set yrange [-0.3:8.3]
set size ratio -1
set tics out nomirror
set ytics 0,2,8
set ylabel "z"
set lmargin 7
set rmargin 2
set tmargin 1
set bmargin 2

colour(i) = word("#2171b5 #238b45 #d94801", i + 1)
label(i) = word("N=10 N=20 N=40", i + 1)

set multiplot layout 4,1 title \
    "Chains driven through an entropic trap array (side view x-z in rod lengths; inlet left, outlet right; 36, 22 and 14 chains of 10, 20 and 40 beads)\n " \
    font ",16"
do for [k=1:ARGC] {
    # the time in the empty corner above the last slit
    set label 1 sprintf("t = %s", ARGV[k]) at 39.5, 5.5 right font ",16"
    if (k == 1) { set key at screen 0.5, screen 0.955 center horizontal } \
    else { unset key }

    plot $walls using 1:2 with lines lw 3 lc rgb "black" notitle, \
         for [i=0:2] sprintf("postProcessing/picture/chains_%s_%d.dat", ARGV[k], i) \
            using 1:2 with linespoints lw 1.5 pt 7 ps 0.3 lc rgb colour(i) \
            title label(i)
}
unset multiplot
