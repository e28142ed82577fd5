# Mean squared radius of gyration of the ring against time
# (postProcessing/polymerCloud/0/statistics.dat, columns time nChains Rg2 ...),
# with the value of an ideal (phantom, unknotted) Gaussian ring of N beads
# and rod length a for scale: Rg2 = N a^2/12. A knotted ring that cannot
# cross itself stays more compact than a phantom ring only when tight; this
# one is long enough that the reference is a guide, not a limit.
# Writes chainSize.png.

N = 400.0
a = 1.0
Rg2ring = N*a**2/12

set terminal pngcairo size 1100,700 font "DejaVu Sans,14"
set output "chainSize.png"

set title "Ring size: the closed trefoil crumples; its knot stays tied"
set xlabel "time (reduced units)"
set ylabel "mean squared radius of gyration (a^2)"
set key top right box opaque
set grid lc rgb "#e0e0e0"
set yrange [0:*]

set label 1 sprintf("ideal ring R_g^2 = N a^2/12 = %.1f", Rg2ring) \
    at graph 0.02, first Rg2ring offset 0,0.7 front tc rgb "#2166ac"

plot "postProcessing/polymerCloud/0/statistics.dat" \
        using 1:3 with lines lw 2.5 lc rgb "#2166ac" title "R_g^2", \
     Rg2ring with lines dt 2 lw 2 lc rgb "#2166ac" notitle
