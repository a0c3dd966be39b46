# fiberTracking: fraction of each length class's escaped fibers per outlet,
# and the counts escaped, against fiber time (scripts/plotOutletFractions).
#   gnuplot -e "table='..'; png='..'; header='Time ..'; title='..'" \
#       plotOutletFractions.gp
set terminal pngcairo size 900,900 noenhanced
set output png
set grid
set key outside right
set xlabel "fiber time [s]"
n = words(header)
# Columns: Time, nC*nO fractions, nC counts
nFrac = 0
do for [i = 2:n] { if (strstrt(word(header, i), "_escaped") == 0) { nFrac = nFrac + 1 } }
nC = n - 1 - nFrac
nO = nFrac/nC
set multiplot layout 2,1 title title
set title "fraction of each length class's escaped fibers, per outlet"
set yrange [0:1]
plot for [i = 2:1 + nFrac] table u 1:i w steps lw 2 \
    linecolor 1 + (i - 2)/nO dashtype 1 + (i - 2)%nO \
    title word(header, i)
set title "fibers escaped per length class"
set yrange [0:*]
plot for [i = 2 + nFrac:n] table u 1:i w steps lw 2 \
    linecolor i - 1 - nFrac title word(header, i)
unset multiplot
