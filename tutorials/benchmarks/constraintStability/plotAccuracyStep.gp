# Accuracy against the step (data/stepBias.dat, written by summarise from
# Allrun step): |bias| in % against deltaT, a curve per method, error bars
# one standard error (filled markers: bias above the exact or reference
# value, open: below); dotted lines at 1, 5 and 10 %; the top axis gives
# delta/a, the first step's rms displacement of neighbouring beads apart
# (newton and exactRods; SHAKE's first step moves them further, its
# velocities keep their components along the rods). newton-subStep (dashed):
# newton with failureAction subStep from newton's first stop on. (e):
# audited crossings of the dense scene with collisions; (f): the share of
# chain-steps where newton's projection had no solution and exactRods gave
# exact rods (newton-subStep: redid them in sub-steps). exactRods-maxDelta
# (black, (a)-(d)): exactRods with solution { maxNeighbourDisplacement
# 0.3; }, at the flow's deltaT, which the cloud takes in K polymer steps of
# deltaT/K (K written by each point; their delta/a about 0.15-0.21, not
# the top axis's). stamp (summarise): the command and the time of the runs,
# under the title.
if (!exists("stamp")) stamp = "command and date not given (summarise gives them)"
set terminal pngcairo size 1800,1080 font "DejaVu Sans,12"
set output "accuracyStep.png"
set multiplot layout 2,3 title "Accuracy against the step: a = m = zeta = kT = 1, failureAction stop; each method up to its first stop, exactRods at every step;\nblack: exactRods with maxNeighbourDisplacement 0.3, at the flow's deltaT taken in K polymer steps of deltaT/K (K by the points)\n{/*0.75 ".stamp."}" font ",14"

methods = "SHAKE-start SHAKE-end RATTLE newton exactRods newton-subStep exactRods-maxDelta"
names = "SHAKE\\_start SHAKE\\_end RATTLE newton exactRods newton\\_subStep exactRods,\\ maxNeighbourDisplacement\\ 0.3"
set style line 1 lc rgb "#b2182b" pt 7 ps 1.3 lw 2
set style line 2 lc rgb "#ef8a62" pt 5 ps 1.3 lw 2
set style line 3 lc rgb "#2166ac" pt 9 ps 1.5 lw 2
set style line 4 lc rgb "#1b7837" pt 13 ps 1.5 lw 2
set style line 5 lc rgb "#762a83" pt 11 ps 1.6 lw 2.5
set style line 6 lc rgb "#35978f" pt 15 ps 1.4 lw 2 dt 2
set style line 7 lc rgb "#000000" pt 7 ps 1.7 lw 2.5
open(i) = (i == 1 ? 6 : i == 2 ? 4 : i == 3 ? 8 : i == 4 ? 12 : i == 5 ? 10 : i == 6 ? 14 : 6)
# a small sideways offset per method, so that equal points stay visible
# (exactRods-maxDelta to the left of exactRods and newton-subStep)
off(i) = (i == 7 ? 0.95 : 1 + 0.03*(i - 3.5))
floor = 0.02
lo(b, e) = (abs(b) - e > floor ? abs(b) - e : floor)
# the runs of method m in scene s that stopped (data/stability.dat)
stops(s, m) = sprintf("< awk '$1 == \"step_%s\" && $2 == \"%s\" && $5 == 0' data/stability.dat", s, m)
scene(q) = (q eq "stretch" ? "extension" : "equilibrium")
# the stable runs of method m, quantity q, in deltaT order
src(q, m) = sprintf("< awk '$2 == \"%s\" && $3 == \"%s\" && $8 == 1 && $6 != \"-\"' data/stepBias.dat | sort -g -k4", q, m)
# exactRods-maxDelta's points of quantity q with their K: deltaT |bias| K
subK(q) = sprintf("< awk 'FNR == NR { if ($2 == \"subCycles\" && $3 == \"exactRods-maxDelta\") K[$1 \" \" $4] = $10; next } $2 == \"%s\" && $3 == \"exactRods-maxDelta\" && $8 == 1 && $6 != \"-\" { print $4, ($6 < 0 ? -$6 : $6), K[$1 \" \" $4] }' data/stepBias.dat data/stepBias.dat", q)

set logscale x
set xrange [0.034:0.75]
set xtics (0.04, 0.057, 0.08, 0.113, 0.16, 0.226, 0.32, 0.453, 0.64)
set format x "%g"
set xlabel "deltaT (a^2 zeta/kT)"
set grid lc rgb "#e0e0e0"
set rmargin 7
unset key

# delta/a on the top axis, from the equilibrium runs of exactRods
deltas = system("awk '$1 == \"equilibrium\" && $2 == \"cos2\" && $3 == \"exactRods\" { printf \"%s %s \", $4, $5 }' data/stepBias.dat")
set x2range [0.034:0.75]
set logscale x2
set x2tics () font ",10" offset 0,-0.3
do for [i = 1:words(deltas):2] {
    set x2tics add (sprintf("%.2g", word(deltas, i + 1) + 0) word(deltas, i) + 0)
}
set x2label "delta/a (rms, first step)" offset 0,-0.5

set logscale y
set format y "%g"
set ylabel "|bias| (%)"
levels = "1 5 10"
do for [l in levels] {
    set label (l." %") at graph 1.01, first (l + 0) left font ",10" tc rgb "#555555"
}

do for [panel in "cos2 Ree2 tau stretch"] {
    # K below exactRods-maxDelta's points (above in (a), whose points lie
    # at the bottom)
    Koffset = -1.4
    if (panel eq "cos2") {
        set title "(a) <cos^2 theta>, 2000 rigid trimers (exact 0.32102)"
        set yrange [0.05:30]
        Koffset = 1.3
    }
    if (panel eq "Ree2") {
        set title "(b) <Ree^2>, 500 chains of 20 beads (exact 19 a^2)"
        set yrange [0.05:100]
    }
    if (panel eq "tau") {
        set title "(c) end-to-end autocorrelation time (1/e), 20 beads\n(against newton at deltaT 0.01)"
        set yrange [0.05:100]
    }
    if (panel eq "stretch") {
        set title "(d) x-extent / L, 128 chains of 50 beads, Wi = 10, strains 7-10\n(against newton at deltaT 0.01)"
        set yrange [0.05:30]
    }
    plot for [i = 1:7] src(panel, word(methods, i)) \
            using ($4*off(i)):(abs($6)) with lines ls i notitle, \
         for [i = 1:7] src(panel, word(methods, i)) \
            using ($6 >= 0 ? $4*off(i) : 1/0):(abs($6)):(lo($6, $7)):(abs($6) + $7) \
            with yerrorbars ls i title word(names, i), \
         for [i = 1:7] src(panel, word(methods, i)) \
            using ($6 < 0 ? $4*off(i) : 1/0):(abs($6)):(lo($6, $7)):(abs($6) + $7) \
            with yerrorbars ls i pt open(i) notitle, \
         subK(panel) using ($1*off(7)):($2):(sprintf("K %d", $3)) \
            with labels offset 0,Koffset font ",10" tc rgb "#000000" notitle, \
         for [i = 1:5] stops(scene(panel), word(methods, i)) \
            using ($4*off(i)):(0.07) with points ls i pt 2 ps 1.8 notitle, \
         stops(scene(panel), word(methods, 7)) \
            using ($4*off(7)):(0.07) with points ls 7 pt 2 ps 1.8 notitle, \
         for [l in levels] l + 0 with lines dt 3 lw 1.5 lc rgb "#555555" notitle
}

# (e) the dense scene: audited crossings per run; the key of every panel
unset label
set key top right box opaque font ",10" samplen 2 spacing 1.05 maxrows 10 width -2
set title "(e) dense scene, collisions on (elasticRods, audit): audited crossings\n50 chains of 20 beads from a 4^3 box, T = 4"
unset logscale y
set yrange [-0.5:12.5]
set ylabel "audited crossings in the run"
set format y "%g"
counts(m) = sprintf("< awk '$2 == \"audited\" && $3 == \"%s\" && $8 == 1' data/stepBias.dat | sort -g -k4", m)
plot for [i = 1:5] counts(word(methods, i)) using ($4*off(i)):($10) \
        with linespoints ls i title word(names, i), \
     NaN with linespoints ls 6 title "newton\\_subStep (a-d)", \
     NaN with linespoints ls 7 title "exactRods, maxNeighbourDisplacement 0.3 (a-d)", \
     NaN with points pt 2 ps 1.8 lc rgb "#333333" title "x: first stop (a-d)", \
     NaN with points pt 6 ps 1.3 lc rgb "#333333" title "open: bias < 0 (a-d)", \
     NaN with lines dt 3 lw 1.5 lc rgb "#555555" title "1, 5, 10 % (a-d)"
unset key

# (f) where exactRods left newton's projection
set title "(f) share of chain-steps where newton's projection had no solution:\nexactRods gave them exact rods (solid),\nnewton-subStep redid them in sub-steps (dashed)"
set logscale y
set format y "10^{%L}"
set yrange [1e-6:1]
set ylabel "share of chain-steps"
set key bottom right box opaque font ",11" samplen 2 maxrows 3
share(q, m) = sprintf("< awk '$2 == \"%s\" && $3 == \"%s\" && $8 == 1 && $9 > 0' data/stepBias.dat | sort -g -k4", q, m)
plot share("cos2", "exactRods") using 4:9 with linespoints lw 2 pt 7 lc rgb "#762a83" title "equilibrium", \
     share("stretch", "exactRods") using 4:9 with linespoints lw 2 pt 5 lc rgb "#e08214" title "extension, Wi = 10", \
     share("collisions", "exactRods") using 4:9 with linespoints lw 2 pt 9 lc rgb "#4d4d4d" title "dense, collisions", \
     share("cos2", "newton-subStep") using ($4*1.03):9 with linespoints lw 2 dt 2 pt 6 lc rgb "#762a83" notitle, \
     share("stretch", "newton-subStep") using ($4*1.03):9 with linespoints lw 2 dt 2 pt 4 lc rgb "#e08214" notitle
unset multiplot
