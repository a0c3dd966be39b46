# fiberTracking: alignment, orientation tensor and fiber counts against fiber
# time from a (joined) fiberStatistics table (scripts/plotAlignment).
#   gnuplot -e "table='...dat'; png='...png'; title='...'" plotAlignment.gp
set terminal pngcairo size 900,1100 noenhanced
set output png
set grid
set key outside right
set xlabel "fiber time [s]"
set multiplot layout 3,1 title title
set title "alignment <|p.e_k|>"
set yrange [0:1]
plot table u 1:6 w l lw 2 t "<|p_x|>", \
     table u 1:7 w l lw 2 t "<|p_y|>", \
     table u 1:8 w l lw 2 t "<|p_z|>"
set title "orientation tensor <pp>"
set yrange [-1:1]
plot table u 1:9 w l lw 2 t "xx", table u 1:12 w l lw 2 t "yy", \
     table u 1:14 w l lw 2 t "zz", table u 1:10 w l dt 2 t "xy", \
     table u 1:11 w l dt 2 t "xz", table u 1:13 w l dt 2 t "yz"
set title "fibers"
set yrange [0:*]
plot table u 1:3 w l lw 2 t "active", table u 1:4 w l lw 2 t "escaped", \
     table u 1:5 w l lw 2 t "deposited"
unset multiplot
