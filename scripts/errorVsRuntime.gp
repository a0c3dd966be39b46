# fiberTracking: error against CPU time of the fiber work, log-log, one line
# per scheme; left: Jeffery case, right: one fiber in the diffuser flow.
#   gnuplot -e "table='...dat'; png='...png'" errorVsRuntime.gp
set terminal pngcairo size 1200,550 noenhanced
set output png
set logscale xy
set grid
set format x "%.0e"
set format y "%.0e"
set xlabel "CPU time of the fiber work [s]"
set key bottom left
set multiplot layout 1,2
set title "Jeffery case: angle error at t = 1 s [deg]"
set ylabel "error"
plot table u ((strcol(1) eq "jeffery" && strcol(2) eq "implicitEuler") ? $4 : 1/0):5 \
        w lp pt 7 t "implicitEuler", \
     table u ((strcol(1) eq "jeffery" && strcol(2) eq "BDF2") ? $4 : 1/0):5 \
        w lp pt 5 t "BDF2"
set title "Diffuser, one fiber, 0.05 s: state error vs converged"
set ylabel "centre/L + orientation error"
plot table u ((strcol(1) eq "diffuser" && strcol(2) eq "implicitEuler") ? $4 : 1/0):5 \
        w lp pt 7 t "implicitEuler", \
     table u ((strcol(1) eq "diffuser" && strcol(2) eq "BDF2") ? $4 : 1/0):5 \
        w lp pt 5 t "BDF2"
unset multiplot
