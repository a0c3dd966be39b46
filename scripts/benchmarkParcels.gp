# fiberTracking: throughput of fibers and parcels (scripts/benchmarkParcels):
# point-steps per second (start-up removed) against the number of points,
# log-log, one line per variant; parcels dashed.
#   gnuplot -e "table='...dat'; png='...png'; variants='a b';
#       pMin=1000; pMax=10000" benchmarkParcels.gp
set terminal pngcairo size 900,600 noenhanced
set output png
set logscale xy
set grid
set xrange [pMin/1.5:pMax*1.5]
set xlabel "points (parcels or fibers)"
set ylabel "point-steps per second (200 steps over 0.4 s)"
set title "fibers (fiberTracking) and parcels (uncoupledKinematicParcelFoam)"
set key outside right
set datafile missing "-"
plot for [v in variants] table \
    u ((strcol(1) eq v && $2 > 1) ? $2 : 1/0):6 w lp pt 7 \
    dt 1 + (strstrt(v, "parcels") > 0) t v
