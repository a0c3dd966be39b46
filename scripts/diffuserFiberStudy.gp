# fiberTracking: <|z3|> = <|p.e_z|> against time for the diffuser fiber
# studies (Andric et al. 2013, Figs. 9-11). Called by diffuserFiberStudy:
#   gnuplot -e "dir='<caseDir>/postProcessing/fiberStudy'" diffuserFiberStudy.gp
# Columns of <variant>.dat (fiberStatistics.dat): 1 time, 3 nActive,
# 8 absP3 = <|z3|> (drawn while fibers are active, column 3 > 0).
set terminal pngcairo size 900,600 noenhanced
set xlabel "t [s]"
set ylabel "<|z3|> (ensemble of active fibers)"
set yrange [0:1]
set grid
set key bottom right

f(v) = sprintf("%s/%s.dat", dir, v)

set output sprintf("%s/fig9-randomWalk.png", dir)
set title "Fig. 9: alignment of initially vertical fibers, random walk on/off"
plot f("base") u 1:($3>0?$8:1/0) w l lw 2 lc rgb "black" t "with random walk", \
     f("noRW") u 1:($3>0?$8:1/0) w l lw 2 dt 2 lc rgb "red" t "without random walk"

set output sprintf("%s/fig10-density.png", dir)
set title "Fig. 10: fiber density rho = 1380 kg/m3 and 5 rho"
plot f("base") u 1:($3>0?$8:1/0) w l lw 1 lc rgb "black" t "rho", \
     f("heavy") u 1:($3>0?$8:1/0) w l lw 3 lc rgb "blue" t "5 rho"

set output sprintf("%s/fig11-segmentLength.png", dir)
set title "Fig. 11: segment length l = 0.2 mm, l/2 and 2l (five segments)"
plot f("base") u 1:($3>0?$8:1/0) w l lw 2 lc rgb "black" t "l", \
     f("short") u 1:($3>0?$8:1/0) w l lw 2 dt 2 lc rgb "red" t "l/2", \
     f("long") u 1:($3>0?$8:1/0) w l lw 2 dt 4 lc rgb "blue" t "2 l"
