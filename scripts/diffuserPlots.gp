#------------------------------------------------------------------------------
# fiberTracking: validation plots of the ERCOFTAC conical diffuser
#
# Usage: gnuplot -e "caseDir='cases/conicalDiffuser'" scripts/diffuserPlots.gp
#        optional: -e "label='default mesh, 99840 cells'"
#
# Reads <caseDir>/postProcessing/validation/{sim,expU,expK}_<st>.dat,
# residuals.dat and axis.dat (written by scripts/diffuserValidation) and
# writes, in the same directory,
#   UW.png          U/U0 and W/U0 against y at the eight stations
#   k.png           k/U0^2 against y at the eight stations
#   station025.png  U, W and k at x = 25 mm   (Figs. 5-6 of Andric et al.)
#   station405.png  U, W and k at x = 405 mm  (Figs. 7-8 of Andric et al.)
#   residuals.png   initial residuals of the SIMPLE iterations
#   axis.png        U_z and k on the centreline (if axis.dat is there)
# Lines: simulation, points: measurements (Clausen et al. 1993). y is the
# wall-normal distance, U the velocity along the wall, W the circumferential
# velocity, U0 = 11.6 m/s.
#------------------------------------------------------------------------------

if (!exists("caseDir")) caseDir = "."
if (!exists("label")) label = "k-epsilon, simpleFoam"

dir = caseDir."/postProcessing/validation"
U0 = 11.6
stations = "-25 025 060 100 175 250 330 405"
names = "-25 25 60 100 175 250 330 405"

sim(s) = dir."/sim_".s.".dat"
expU(s) = dir."/expU_".s.".dat"
expK(s) = dir."/expK_".s.".dat"

set terminal pngcairo size 1600,900 font ",11"
set grid
set key top right

# ---- U and W at all stations ------------------------------------------------
set output dir."/UW.png"
set multiplot layout 2,4 \
    title "Conical diffuser: U and W along the wall-normal traverses (" \
          .label.")"
set xlabel "y [mm]"
set ylabel "U/U_0, W/U_0"
set yrange [-0.1:1.2]
do for [i=1:8] {
    s = word(stations, i)
    set title "x = ".word(names, i)." mm"
    if (i == 1) { set key at graph 0.95, graph 0.8 } else { unset key }
    plot sim(s) u 1:($2/U0) w l lw 2 lc rgb "red" t "U sim", \
         expU(s) u 1:($2/U0) w p pt 7 ps 0.8 lc rgb "red" t "U exp", \
         sim(s) u 1:($3/U0) w l lw 2 lc rgb "blue" t "W sim", \
         expU(s) u 1:($3/U0) w p pt 5 ps 0.8 lc rgb "blue" t "W exp"
}
unset multiplot
set key top right

# ---- k at all stations ------------------------------------------------------
set output dir."/k.png"
set multiplot layout 2,4 \
    title "Conical diffuser: k along the wall-normal traverses (".label.")"
set xlabel "y [mm]"
set ylabel "k/U_0^2"
set yrange [0:*]
set xrange [0:80]
do for [i=1:8] {
    s = word(stations, i)
    set title "x = ".word(names, i)." mm"
    if (i == 1) { set key top right } else { unset key }
    plot sim(s) u 1:($4/U0**2) w l lw 2 lc rgb "dark-green" t "k sim", \
         expK(s) u 1:($2/U0**2) w p pt 7 ps 0.8 lc rgb "dark-green" t "k exp"
}
unset multiplot
set xrange [*:*]
set key top right

# ---- the paper's two stations -----------------------------------------------
set terminal pngcairo size 1200,500 font ",12"
do for [s in "025 405"] {
    set output dir."/station".s.".png"
    set multiplot layout 1,2 title "Conical diffuser, x = " \
        .(s eq "025" ? "25" : s)." mm (".label.")"
    set title "velocities"
    set xlabel "y [mm]"
    set ylabel "U/U_0, W/U_0"
    set yrange [-0.1:1.2]
    set key bottom right
    plot sim(s) u 1:($2/U0) w l lw 2 lc rgb "red" t "U sim", \
         expU(s) u 1:($2/U0) w p pt 7 lc rgb "red" t "U exp", \
         sim(s) u 1:($3/U0) w l lw 2 lc rgb "blue" t "W sim", \
         expU(s) u 1:($3/U0) w p pt 5 lc rgb "blue" t "W exp"
    set title "turbulent kinetic energy"
    set ylabel "k/U_0^2"
    set yrange [0:*]
    set xrange [0:80]
    set key top right
    plot sim(s) u 1:($4/U0**2) w l lw 2 lc rgb "dark-green" t "k sim", \
         expK(s) u 1:($2/U0**2) w p pt 7 lc rgb "dark-green" t "k exp"
    set xrange [*:*]
    unset multiplot
}

# ---- centreline -------------------------------------------------------------
axisFile = dir."/axis.dat"
if (system("test -s '".axisFile."' && echo 1 || echo 0") eq "1") {
    set terminal pngcairo size 900,600 font ",12"
    set output dir."/axis.png"
    set title "Centreline, simulation (".label."); cone from z = 0 to 0.51 m"
    set xlabel "z [m]"
    set ylabel "U_z/U_0"
    set y2label "k/U_0^2"
    set yrange [-0.1:1.1]
    set y2range [0:*]
    set ytics nomirror
    set y2tics
    set xrange [-0.5:1.1]
    set arrow 1 from 0,graph 0 to 0,graph 1 nohead dt 2
    set arrow 2 from 0.51,graph 0 to 0.51,graph 1 nohead dt 2
    set key top right
    plot axisFile u 1:($2/U0) w l lw 2 lc rgb "red" t "U_z", \
         axisFile u 1:($3/U0**2) axes x1y2 w l lw 2 lc rgb "dark-green" t "k"
    unset arrow 1
    unset arrow 2
    unset y2label
    unset y2tics
    set ytics mirror
    set xrange [*:*]
}

# ---- residuals --------------------------------------------------------------
resFile = dir."/residuals.dat"
if (system("test -s '".resFile."' && echo 1 || echo 0") eq "1") {
    set terminal pngcairo size 900,600 font ",12"
    set output dir."/residuals.png"
    set title "Initial residuals, simpleFoam (".label.")"
    set xlabel "iteration"
    set ylabel "initial residual"
    set logscale y
    set format y "10^{%L}"
    set yrange [*:*]
    set key top right
    plot for [c=2:7] resFile u 1:c w l lw 2 \
        t word("Ux Uy Uz p k epsilon", c-1)
}
unset output
