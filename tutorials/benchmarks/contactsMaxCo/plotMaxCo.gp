# Contacts against maxCo (Allrun): the largest rod-length error at any
# step's end and the cloud's CPU per bead-step, both treatments, three
# scenes. A run that stopped early is drawn with an open point at its last
# maxCo.
set terminal pngcairo size 1300,520 font ",11"
set output "maxCo.png"
set multiplot layout 1,2 title "Contacts in flowing devices: the paper's treatment against rods through the chains, re-projected with rigid impact zones (exactRods); the paper's with newton"
set logscale x 2
set xrange [0.2:2.5]
set xlabel "maxCo (the flow's Courant number)"
set key top left font ",9"
set grid

data = "data/maxCo.dat"
scenes = "contraction12 contraction40 postArray"
colours = "#1b9e77 #d95f02 #7570b3"

set logscale y
set format y "10^{%L}"
set ylabel "largest relative rod-length error at a step's end"
set yrange [1e-12:10]
plot for [i=1:3] data using 2:(strcol(1) eq word(scenes, i) && strcol(3) eq "paper" ? ($6 > 0 ? $6 : 1e-12) : 1/0) \
        with linespoints lw 2 pt 7 lc rgb word(colours, i) title word(scenes, i)." paper's", \
     for [i=1:3] data using 2:(strcol(1) eq word(scenes, i) && strcol(3) eq "default" ? ($6 > 0 ? $6 : 1e-12) : 1/0) \
        with linespoints lw 2 dt 2 pt 5 lc rgb word(colours, i) title word(scenes, i)." default", \
     for [i=1:3] data using 2:(strcol(1) eq word(scenes, i) && $5 < $4 ? $6 : 1/0) \
        with points pt 6 ps 3 lc rgb word(colours, i) notitle

unset logscale y
set format y "%g"
set yrange [0:*]
set ylabel "cloud CPU per bead-step (us)"
plot for [i=1:3] data using 2:(strcol(1) eq word(scenes, i) && strcol(3) eq "paper" && $15 > 0 ? 1e6*$14/$15 : 1/0) \
        with linespoints lw 2 pt 7 lc rgb word(colours, i) title word(scenes, i)." paper's", \
     for [i=1:3] data using 2:(strcol(1) eq word(scenes, i) && strcol(3) eq "default" && $15 > 0 ? 1e6*$14/$15 : 1/0) \
        with linespoints lw 2 dt 2 pt 5 lc rgb word(colours, i) title word(scenes, i)." default"
unset multiplot
