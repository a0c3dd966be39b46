# fiberTracking: velocity profiles of cases/fiberChannel (Allrun), one-way
# and two-way coupled at two mass loadings, with the closed forms
#   gnuplot -e "out='postProcessing/profiles.png'" plotProfiles.gp
set terminal pngcairo size 800,600 noenhanced
set output out
set grid
set key top center box opaque
set yrange [0:7]
set xlabel "y [mm]"
set ylabel "u [mm/s]"
set title "Vertical channel, glass fibers falling in a glycerol-like liquid"
h = 0.01; nu = 1.26984126984e-3; f0 = 0.5
Vf = 5*pi/4*(4e-5)**2*4e-4
f(n) = f0 - n*(2500 - 1260)*Vf*9.81/(1260*h**3)
u(y, n) = 1e3*f(n)*y*(h - y)/(2*nu)
plot "runs/oneWay/profile.dat" u ($1*1e3):($2*1e3) w p pt 7 t "one-way", \
     "runs/loading1/profile.dat" u ($1*1e3):($2*1e3) w p pt 5 \
         t "two-way, mass loading 0.01", \
     "runs/loading2/profile.dat" u ($1*1e3):($2*1e3) w p pt 9 \
         t "two-way, mass loading 0.02", \
     [0:10] u(x*1e-3, 0) w l lc 1 t "Poiseuille, drive only", \
     [0:10] u(x*1e-3, 2000) w l lc 2 dt 2 \
         t "drive less the fibers' weight spread evenly", \
     [0:10] u(x*1e-3, 4000) w l lc 3 dt 2 notitle
