#------------------------------------------------------------------------------
# fiberTracking: plot of a Jeffery orbit, simulated and analytic angle
#
# Usage: gnuplot -e "caseDir='cases/jefferyOrbit'" scripts/plotJeffery.gp
#
# Reads  <caseDir>/postProcessing/fibers/0/jefferyAngle.dat
#        <caseDir>/postProcessing/fibers/0/jeffery.dat  (optional)
# both written by scripts/jefferyPeriod, and writes
#        <caseDir>/postProcessing/fibers/0/jefferyOrbit.png
# The periods can also be given: -e "Tm=1.08; Ta=0.98579"
#------------------------------------------------------------------------------

if (!exists("caseDir")) caseDir = "."

dir = caseDir."/postProcessing/fibers/0"
angleFile = dir."/jefferyAngle.dat"
resultFile = dir."/jeffery.dat"
pngFile = dir."/jefferyOrbit.png"

# Periods from jeffery.dat unless given with -e
if (!exists("Tm") || !exists("Ta")) {
    if (system("test -s '".resultFile."' && echo 1 || echo 0") eq "1") {
        stats resultFile using 1 nooutput name "M"
        stats resultFile using 2 nooutput name "A"
        Tm = M_max
        Ta = A_max
    }
}

if (exists("Tm") && exists("Ta")) {
    err = 100.0*(Tm/Ta - 1.0)
    plotTitle = sprintf( \
        "Jeffery orbit: measured T = %.4f s, analytic T = %.4f s, " \
        ."error %+.2f %%", Tm, Ta, err)
} else {
    plotTitle = "Jeffery orbit (period not measured)"
}

if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {
    set terminal pngcairo size 900,600 enhanced font "sans,11"
} else {
    set terminal png size 900,600
}
set output pngFile

set title plotTitle
set xlabel "t [s]"
set ylabel "{/Symbol f} = atan2(p_x, p_y) [deg]"
set grid
set key left top box opaque
set ytics 90
set mytics 2

plot angleFile using 1:3 with lines lw 2 lc rgb "black" \
        title "analytic (Jeffery, Cox r_e)", \
     angleFile using 1:2 with lines lw 2 dt 2 lc rgb "red" \
        title "simulation"

set output

#------------------------------------------------------------------------------
