# Contacts against maxCo (Allrun): the largest rod-length error at any
# step's end and the cloud's CPU per bead-step, both treatments, three
# scenes. A run that stopped (a chain's constraint failed in every
# sub-step) is ringed at the error it had reached; it has no cost point.
# The scenes are drawn slightly apart in maxCo so that equal values show.
# stamp (gnuplot -e "stamp='...'"): the data's command and when its runs
# finished, under the title.
if (!exists("stamp")) stamp = "data/maxCo.dat: command and date not given"
set terminal pngcairo size 1300,580 font ",11"
set output "maxCo.png"
set multiplot layout 1,2 title "Contacts in flowing devices: the paper's treatment (dumbbell impulses after the constraint, newton) against the default\n(impulses through the chains' rods, rods meeting wall edges, re-projected with contact constraints, rigid impact zones last, exactRods); ringed: the run stopped\n{/*0.9 ".stamp."}"
set logscale x 2
set xrange [0.2:2.5]
set xtics ("0.25" 0.25, "0.5" 0.5, "1" 1, "2" 2)
set xlabel "maxCo (the flow's Courant number)"
set key top left font ",9" opaque
set grid

data = "data/maxCo.dat"
scenes = "contraction12 contraction40 postArray"
colours = "#1b9e77 #d95f02 #7570b3"
shift(i) = 0.94 + 0.06*(i - 1)

# Rows of one scene and treatment: maxCo, rod error, stopped (0/1), cost
rows(s, t) = sprintf("< awk '$1 == \"%s\" && $3 == \"%s\" { print $2, $6, ($7 == \"NA\"), ($15 > 0 ? 1e6*$14/$15 : \"NaN\") }' %s", s, t, data)

set logscale y
set format y "10^{%L}"
set ylabel "largest relative rod-length error at a step's end"
set key center right
set yrange [1e-12:30]
plot for [i=1:3] rows(word(scenes, i), "paper") using ($1*shift(i)):2 \
        with linespoints lw 2 pt 7 lc rgb word(colours, i) title word(scenes, i)." paper's", \
     for [i=1:3] rows(word(scenes, i), "default") using ($1*shift(i)):2 \
        with linespoints lw 2 dt 2 pt 5 lc rgb word(colours, i) title word(scenes, i)." default", \
     for [i=1:3] rows(word(scenes, i), "paper") using ($1*shift(i)):($3 > 0.5 ? $2 : 1/0) \
        with points pt 6 ps 3 lw 2 lc rgb word(colours, i) notitle

set format y "%g"
set yrange [1:1000]
set ylabel "cloud CPU per bead-step (us; elasticRods' audit on in every run)"
set key bottom right
plot for [i=1:3] rows(word(scenes, i), "paper") using ($1*shift(i)):4 \
        with linespoints lw 2 pt 7 lc rgb word(colours, i) title word(scenes, i)." paper's", \
     for [i=1:3] rows(word(scenes, i), "default") using ($1*shift(i)):4 \
        with linespoints lw 2 dt 2 pt 5 lc rgb word(colours, i) title word(scenes, i)." default"
unset multiplot
