# fiberTracking test helper (tests/periodicSector): fiberState.dat -> per
# fiber: id, largest position error [m], largest orientation error,
# number of sector crossings.
# Deviation of each fiber from solid-body rotation at 2 rad/s (azimuth
# phi = atan2(y, z)) about x plus 1 m/s along x, in quantities a rotation
# about x leaves alone: axial position, radius, azimuth modulo 90 degrees
# (the sector), and the orientation in the local frame (p_x, p_r, p_phi)
function wrap(a) { while (a > pi/4) a -= pi/2; while (a <= -pi/4) a += pi/2; return a }
BEGIN { pi = atan2(0, -1) }
!/^#/ && NF {
  id = $2; r = sqrt($4^2 + $5^2); phi = atan2($4, $5)
  pr = ($7*$4 + $8*$5)/r; pf = ($7*$5 - $8*$4)/r
  if (!(id in x0)) { x0[id] = $3; r0[id] = r; f0[id] = phi; px0[id] = $6
      pr0[id] = pr; pf0[id] = pf; fl[id] = phi }
  dphi = wrap(phi - (f0[id] + 2*$1))
  e = sqrt(($3 - x0[id] - $1)^2 + (r - r0[id])^2 + (r*dphi)^2)
  ep = sqrt(($6 - px0[id])^2 + (pr - pr0[id])^2 + (pf - pf0[id])^2)
  if ((phi - fl[id])^2 > 0.5) n[id]++; fl[id] = phi
  if (e > em[id]) em[id] = e; if (ep > epm[id]) epm[id] = ep }
END { for (id in em) printf "%s %.3g %.3g %d\n", id, em[id], epm[id], n[id] }
