# Largest stable time step per method and case (data/largest.dat, written
# by summarise): one marker per method; bars up to the first unstable step.
# exactRods, stable at every step tried, has no bar: its marker is the
# largest step tried. stamp (summarise): the command and the time of the
# runs, under the title.
if (!exists("stamp")) stamp = "command and date not given (summarise gives them)"
set terminal pngcairo size 1300,650 font "DejaVu Sans,12"
set output "stability.png"
set title "Largest stable deltaT (markers) and smallest unstable deltaT tried (top of the bar)\nexactOU; failureAction stop; maxIterations 20000 (newton, exactRods 50); exactRods: stable at every step tried (no bar)\n{/*0.8 ".stamp."}"
set ylabel "deltaT (reduced units; a = kT = 1)"
set logscale y
set format y "10^{%L}"
set yrange [0.004:30]
set xrange [-0.6:6.6]
set grid ytics lc rgb "#e0e0e0"
set key inside left top Left reverse box opaque
set bmargin 5
set xtics ("(a) trefoil\nN=400, T=10\nzeta=10, m=1" 0, "(b) extension\nN=100, Wi=34, T=60\nzeta=10, m=1" 1, \
           "(c) quiescent\nN=100, T=20\nzeta=10, m=1" 2, "(c)\nzeta=1\nm=1" 3, \
           "(c)\nzeta=0.1\nm=1" 4, "(c)\nzeta=10\nm=10" 5, \
           "(c)\nzeta=10\nm=100" 6) scale 0 font ",11"
set style line 1 lc rgb "#b2182b" pt 7 ps 1.6
set style line 2 lc rgb "#ef8a62" pt 5 ps 1.6
set style line 3 lc rgb "#2166ac" pt 9 ps 1.8
set style line 4 lc rgb "#67a9cf" pt 11 ps 1.8
set style line 5 lc rgb "#1b7837" pt 13 ps 1.8
set style line 6 lc rgb "#7fbf7b" pt 15 ps 1.6
set style line 7 lc rgb "#762a83" pt 3 ps 2.2 lw 2
m(s) = (s eq "SHAKE-start" ? 0 : s eq "SHAKE-end" ? 1 : s eq "RATTLE" ? 2 : \
        s eq "RATTLE-end" ? 3 : s eq "newton" ? 4 : 5)
off(s) = (m(s) - 2.5)*0.12
sel(s, v) = (strcol(3) eq s ? v : 1/0)
names = "SHAKE-start SHAKE-end RATTLE RATTLE-end newton newton-end exactRods"
titles = "SHAKE\\_start SHAKE\\_end RATTLE\\_start RATTLE\\_end newton\\_start newton\\_end exactRods"
plot for [i=1:7] "data/largest.dat" \
        using ($1 + (i - 4)*0.115):(sel(word(names, i), $4)):($4):(strcol(5) eq "-" ? $4 : $5) \
        with yerrorbars ls i lw 1.5 pt 0 notitle, \
     for [i=1:7] "data/largest.dat" \
        using ($1 + (i - 4)*0.115):(sel(word(names, i), $4)) \
        with points ls i title word(titles, i)
