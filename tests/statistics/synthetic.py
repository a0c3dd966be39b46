#!/usr/bin/python3
# -----------------------------------------------------------------------------
# fiberTracking: synthetic fiber runs with known statistics, for the tests of
# scripts/fiberStatistics.py.
#
# Usage: synthetic.py <runDir> <nFibers> <seed> <biasX>
#
# Writes <runDir>/0/fiberState.dat and fiberEvents.dat as fiberTracking
# does.  Every fiber is injected at t = 0 and written at the ten output
# times 0.01 ... 0.10; its orientation is uniform on the sphere, drawn anew
# for each of the five windows of two output times and held within a window
# (states of one fiber in a window are perfectly correlated).  Uniform on the
# sphere: <|p_k|> = 1/2, var |p_k| = 1/12, <p_k p_k> = 1/3, var = 4/45.
# biasX > 0 mixes the x axis in: p is replaced, with probability biasX, by
# +-e_x (so <|p_x|> = 1/2 + biasX/2).  Fates: outlet 'a' with probability
# 0.3 (escape at t uniform in (0, 0.1)), 'b' with 0.5, in the domain 0.2,
# whatever the length: 1, 2 or 3 mm by id (three length classes).
# -----------------------------------------------------------------------------
import os
import sys

import numpy as np

run, n, seed, bias = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), \
    float(sys.argv[4])
rng = np.random.default_rng(seed)
os.makedirs(os.path.join(run, '0'), exist_ok=True)
times = 0.01*np.arange(1, 11)
with open(os.path.join(run, '0', 'fiberState.dat'), 'w') as f:
    f.write('# Time id cx cy cz px py pz vx vy vz wx wy wz\n')
    p = np.zeros((n, 3))
    for k, t in enumerate(times):
        if k % 2 == 0:
            p = rng.normal(size=(n, 3))
            p /= np.linalg.norm(p, axis=1)[:, None]
            x = rng.random(n) < bias
            p[x] = np.array([1.0, 0, 0])*np.sign(rng.random(x.sum()) - 0.5)[
                :, None]
        for i in range(n):
            f.write('%g %d 0 0 0 %.10g %.10g %.10g 0 0 0 0 0 0\n'
                    % (t, i, p[i, 0], p[i, 1], p[i, 2]))
u = rng.random(n)
tEsc = 0.1*rng.random(n)
with open(os.path.join(run, '0', 'fiberEvents.dat'), 'w') as f:
    f.write('# Time id set event patch nSegments length diameter cx cy cz'
            ' px py pz\n')
    for i in range(n):
        f.write('0 %d feed injected inlet 5 %g 2e-05 0 0 0 1 0 0\n'
                % (i, 1e-3*(1 + i % 3)))
    for i in range(n):
        if u[i] < 0.8:
            o = 'a' if u[i] < 0.3 else 'b'
            f.write('%g %d feed escaped %s 5 0.001 2e-05 0 0 0 1 0 0\n'
                    % (tEsc[i], i, o))
