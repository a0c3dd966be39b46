# fiberTracking: error against CPU time of the fiber work for the two
# sub-step controls, log-log, one panel per scene (scripts/subStepStudy).
#   gnuplot -e "table='...dat'; png='...png'; scenes='jeffery tjunction'" \
#       subStepStudy.gp
set terminal pngcairo size 1200,1000 noenhanced
set output png
set logscale xy
set grid
set format x "%.0e"
set format y "%.0e"
set xlabel "CPU time of the fiber work [s]"
set ylabel "error"
set key top right
col(s) = (s eq "diffuser") ? 7 : 6
sel(s, c) = (strcol(1) eq s && strcol(2) eq c && column(col(s)) > 0) ? $4 : 1/0
title(s) = (s eq "jeffery") ? "Jeffery, one segment: angle error at 1 s [deg]" : \
    (s eq "diffuser") ? "Diffuser Fig. 9, 50 fibers, no walk: ramp time, rel. error" : \
    (s eq "tjunction") ? "TJunction, 200 fibers: max |<|p.e_k|> - ref|" : \
    "pitzDaily, 50 fibers: max |<|p.e_k|> - ref|"
n = words(scenes)
set multiplot layout (n > 2 ? 2 : 1), (n > 1 ? 2 : 1)
do for [i = 1:n] {
    s = word(scenes, i)
    set title title(s)
    plot table u (sel(s, "paper")):(column(col(s))) w lp pt 7 \
             t "paper (Eq. 22)", \
         table u (sel(s, "tolerance")):(column(col(s))) w lp pt 5 \
             t "tolerance"
}
unset multiplot
