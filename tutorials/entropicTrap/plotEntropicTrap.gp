# The trap array in the x-z plane (side view) with the chains projected on
# it, at four times. Usage: gnuplot -c plotEntropicTrap.gp <t1> <t2> <t3> <t4>
# Reads postProcessing/picture/chains_<t>_<type>.dat (type 0-2: N10, N30,
# N90); writes entropicTrap.png.

set terminal pngcairo size 1600,1800 font "DejaVu Sans,14"
set output "entropicTrap.png"

# Channel outline: floor z = 0; first well 12 deep and 12 long, the
# other wells 8 deep and 6 long, slits 1 deep and 4 long
$walls << EOD
0 12
0 0
46 0
46 1

0 12
12 12
12 1
16 1
16 8
22 8
22 1
26 1
26 8
32 8
32 1
36 1
36 8
42 8
42 1
46 1
EOD

set xrange [-0.5:46.5]
set yrange [-0.3:12.3]
set size ratio -1
set tics out nomirror
set ytics 0,2,12
set ylabel "z"
set lmargin 7
set rmargin 2
set tmargin 1
set bmargin 2

colour(i) = word("#2171b5 #238b45 #d94801", i + 1)
label(i) = word("N=10 N=30 N=90", i + 1)

set multiplot layout 4,1 title \
    "Uncrossable chains driven through an entropic trap array (side view x-z in rod lengths; inlet left, outlet right)\nthe first of 15 batches: 4, 4 and 1 chains of 10, 30 and 90 beads\n " \
    font ",16"
do for [k=1:ARGC] {
    # the time in the empty corner above the last wells
    set label 1 sprintf("t = %s", ARGV[k]) at 45.5, 10.5 right font ",16"
    if (k == 1) { set key at screen 0.5, screen 0.958 center horizontal } \
    else { unset key }

    plot $walls using 1:2 with lines lw 3 lc rgb "black" notitle, \
         for [i=0:2] sprintf("postProcessing/picture/chains_%s_%d.dat", ARGV[k], i) \
            using 1:2 with linespoints lw 1.5 pt 7 ps 0.3 lc rgb colour(i) \
            title label(i)
}
unset multiplot
