# Mean squared radius of gyration and end-to-end distance of the chain
# against time (postProcessing/polymerCloud/0/statistics.dat, columns
# time nChains Rg2 Ree2 ...), with the freely jointed chain's equilibrium
# values for N = 400 beads and rod length a = 1:
#     Rg2 = a^2 (N^2 - 1)/(6 N),   Ree2 = (N - 1) a^2
# Writes chainSize.png.

N = 400.0
a = 1.0
Rg2eq = a**2*(N**2 - 1)/(6*N)
Ree2eq = (N - 1)*a**2

set terminal pngcairo size 1100,700 font "DejaVu Sans,14"
set output "chainSize.png"

set title "Chain size: the cut trefoil contracts toward a random coil"
set xlabel "time (reduced units)"
set ylabel "mean squared size (a^2)"
set key top right box opaque
set grid lc rgb "#e0e0e0"
set yrange [0:*]

set label 1 sprintf("freely jointed R_{ee}^2 = %.0f", Ree2eq) \
    at graph 0.02, first Ree2eq offset 0,0.7 front tc rgb "#b2182b"
set label 2 sprintf("freely jointed R_g^2 = %.1f", Rg2eq) \
    at graph 0.02, first Rg2eq offset 0,0.7 front tc rgb "#2166ac"

plot "postProcessing/polymerCloud/0/statistics.dat" \
        using 1:4 with lines lw 1.5 lc rgb "#f4a582" title "R_{ee}^2", \
     ''  using 1:3 with lines lw 2.5 lc rgb "#2166ac" title "R_g^2", \
     Ree2eq with lines dt 2 lw 2 lc rgb "#b2182b" notitle, \
     Rg2eq with lines dt 2 lw 2 lc rgb "#2166ac" notitle
