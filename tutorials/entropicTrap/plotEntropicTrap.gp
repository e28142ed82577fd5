# The trap array in the x-z plane (side view) with the chains projected on
# it, at four times. Usage: gnuplot -c plotEntropicTrap.gp <t1> <t2> <t3> <t4>
# Reads postProcessing/picture/chains_<t>_<type>.dat (type 0-3: N2, N10,
# N20, N40); writes entropicTrap.png.

set terminal pngcairo size 1600,1000 font "DejaVu Sans,14"
set output "entropicTrap.png"

# Channel outline: floor z = 0; wells 5 deep, slits 1 deep
$walls << EOD
0 5
0 0
40 0
40 1

0 5
6 5
6 1
10 1
10 5
16 5
16 1
20 1
20 5
26 5
26 1
30 1
30 5
36 5
36 1
40 1
EOD

set xrange [-0.5:40.5]
set yrange [-0.3:5.3]
set size ratio -1
set tics out nomirror
set ytics 0,1,5
set ylabel "z"
set lmargin 7
set rmargin 2
set tmargin 1.5
set bmargin 1.5

colour(i) = word("#969696 #2171b5 #238b45 #d94801", i + 1)
label(i) = word("N=2 N=10 N=20 N=40", i + 1)

set multiplot layout 4,1 title \
    "Chains driven through an entropic trap array (side view x-z in rod lengths; inlet left, outlet right; 16 chains of each length)\n " \
    font ",16"
do for [k=1:ARGC] {
    set title sprintf("t = %s", ARGV[k]) offset 0,-0.6
    if (k == 1) { set key at screen 0.5, screen 0.955 center horizontal } \
    else { unset key }

    plot $walls using 1:2 with lines lw 3 lc rgb "black" notitle, \
         for [i=0:3] sprintf("postProcessing/picture/chains_%s_%d.dat", ARGV[k], i) \
            using 1:2 with linespoints lw 1.5 pt 7 ps 0.3 lc rgb colour(i) \
            title label(i)
}
unset multiplot
