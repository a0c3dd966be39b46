# fiberTracking test helper (tests/periodicSector): fiberState.dat of the
# sector run (first file) against that of the full 360-degree run (second):
# each full-mesh state is turned by the multiple of 90 degrees about x that
# brings it nearest to the sector state (the sector's periodic images are
# one point); per fiber: id, largest centre difference [m], largest
# orientation difference, number of states compared.
BEGIN { pi = atan2(0, -1) }
FNR == 1 { f++ }
/^#/ || !NF { next }
f == 1 { key = $1 " " $2; X[key] = $3; Y[key] = $4; Z[key] = $5
         PX[key] = $6; PY[key] = $7; PZ[key] = $8; next }
{
    key = $1 " " $2
    if (!(key in X)) next
    best = -1
    for (m = 0; m < 4; m++)
    {
        a = m*pi/2; c = cos(a); s = sin(a)
        y = $4*c + $5*s; z = $5*c - $4*s
        e = sqrt(($3 - X[key])^2 + (y - Y[key])^2 + (z - Z[key])^2)
        if (best < 0 || e < best) { best = e; mb = m }
    }
    a = mb*pi/2; c = cos(a); s = sin(a)
    py = $7*c + $8*s; pz = $8*c - $7*s
    ep = sqrt(($6 - PX[key])^2 + (py - PY[key])^2 + (pz - PZ[key])^2)
    if (best > em[$2]) em[$2] = best
    if (ep > epm[$2]) epm[$2] = ep
    n[$2]++
}
END { for (id in em) printf "%s %.3g %.3g %d\n", id, em[id], epm[id], n[id] }
