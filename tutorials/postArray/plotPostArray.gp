# Chains over the flow speed in the post array's mid-depth plane, at four
# times. Usage: gnuplot -c plotPostArray.gp <t1> <t2> <t3> <t4>
# Reads postProcessing/picture/{speed,chains}_<t>.dat; writes postArray.png.
# Each cell of the mid-depth layer is drawn as a square of its size (1, or
# 1/2 next to the posts) at its centre; the posts are the grey holes,
# outlined by their exact circles (radius 3, dashed).

set terminal pngcairo size 1600,760 font "DejaVu Sans,14"
set output "postArray.png"

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
set style fill solid noborder

# Grey behind the cells: the posts (no cells) show as grey holes
set object 10 rectangle from graph 0, graph 0 to graph 1, graph 1 behind \
    fillcolor rgb "#a0a0a0" fillstyle solid noborder

posts = "-12 -5  -12 5  0 0  12 -5  12 5"
do for [k=1:5] {
    set object k circle at real(word(posts, 2*k - 1)), real(word(posts, 2*k)) size 3 \
        front fillstyle empty border lc rgb "#303030" lw 1 dt 2
}

set multiplot layout 2,2 title \
    "Kramers chains (20 beads) carried through a staggered array of posts (snappyHexMesh): flow solved, walls, outlet" \
    font ",16"
do for [i=1:ARGC] {
    set title sprintf("t = %s", ARGV[i])
    plot sprintf("postProcessing/picture/speed_%s.dat", ARGV[i]) \
            using 1:2:4:4:3 with boxxyerror lc palette, \
         sprintf("postProcessing/picture/chains_%s.dat", ARGV[i]) \
            using 1:2 with lines lw 2 lc rgb "#d94801"
}
unset multiplot
