#!/usr/bin/python3
# -----------------------------------------------------------------------------
# fiberTracking: ensemble statistics of a fiber run with standard errors, and
# the comparison of two runs of the same fibers (two step settings).
#
# Usage:
#   fiberStatistics.py stats <runDir> [-windows W] [-batches B] [-t0 T]
#   fiberStatistics.py compare <judgedDir> <referenceDir> [-windows W]
#       [-batches B] [-t0 T] [-z Z] [-label NAME] [-table FILE]
#
# <runDir> is a case's postProcessing/<object name> folder (the newest
# start-time folder under it is read): fiberState*.dat (states at the output
# times) and, where the object has eventLog on, fiberEvents*.dat.
#
# Statistics (what a user reads of a fiber run):
#   - absP.<k>.w<i>, pp.<kk>.w<i>: <|p.e_k|> and the diagonal of <pp> of the
#     fibers in the domain in time window i (W equal windows from -t0, default
#     the first output time, to the last output time; every fiber state of
#     the window counts once);
#   - fate.<outcome>[.<class>]: the fraction of the injected fibers that left
#     through an outlet, deposited, or are still in the domain at the end
#     (per length class, three equal classes of the injected lengths, where
#     the lengths are distributed);
#   - escapeAbsP.<outlet>.<k>: <|p.e_k|> of the fibers at their escape;
#   - residence.<outlet>.median, .p90: median and 90th percentile of the
#     residence time (escape time less injection time), in seconds.
#
# Standard errors: batch means over fibers.  The fibers are split into B
# batches by id (id mod B); a statistic is computed on each batch, and its
# standard error is the standard deviation of the B batch values over
# sqrt(B).  Fibers do not interact (one-way coupling) and their initial
# places, orientations and eddies come from independent random streams, so
# the batches are independent samples given the flow; all the correlation
# within a fiber (its states at many times in one window, its escape
# orientation and time) stays inside one batch.  With B = 20 the estimate
# has 19 degrees of freedom: 3 standard errors are a two-sided 99.3 % band.
#
# compare: for each statistic, the difference judged - reference with the
# combined standard error sqrt(se_j^2 + se_r^2) (conservative where the
# two runs of the same fibers are positively correlated) and the paired
# one (the batch means of the differences, valid for the same fibers);
# PASS when |difference| <= Z combined standard errors (Z = 3).  The
# paired z (difference over the paired standard error) is reported too: it
# can detect smaller biases where the runs stay correlated (early times),
# and the summary line counts the statistics beyond Z paired standard
# errors with the largest of their differences.  A
# statistic with fewer than B/2 batches that hold data is left out (n/a).
# -----------------------------------------------------------------------------
import glob
import math
import os
import sys

import numpy as np


def newest(run, pattern):
    """The files of a pattern in the newest start-time folder of a run that
    holds any."""
    best, files = None, []
    for d in glob.glob(os.path.join(run, '*')):
        f = sorted(glob.glob(os.path.join(d, pattern)))
        if not f:
            continue
        try:
            t = float(os.path.basename(d))
        except ValueError:
            continue
        if best is None or t > best:
            best, files = t, f
    return files


def readStates(run):
    files = newest(run, 'fiberState*.dat')
    if not files:
        sys.exit('fiberStatistics: no fiberState*.dat under ' + run)
    rows = [np.loadtxt(f, comments='#', ndmin=2) for f in files]
    a = np.vstack([r for r in rows if r.size])
    # time id cx cy cz px py pz ...
    return a[:, 0], a[:, 1].astype(int), a[:, 5:8]


def readEvents(run):
    files = newest(run, 'fiberEvents*.dat')
    ev = []
    for f in files:
        for line in open(f):
            if line.startswith('#') or not line.strip():
                continue
            w = line.split()
            # Time id set event patch nSegments length diameter c(3) p(3)
            ev.append((float(w[0]), int(w[1]), w[2], w[3], w[4],
                       float(w[6]), np.array([float(x) for x in w[11:14]])))
    return ev


class Run:
    def __init__(self, run):
        self.t, self.id, self.p = readStates(run)
        self.events = readEvents(run)
        inj, esc = {}, {}
        for (t, i, s, kind, patch, L, p) in self.events:
            if kind == 'injected':
                inj[i] = (t, L)
            else:
                esc[i] = (t, kind, patch, p)
        self.injected = inj
        self.left = esc


def windows(runs, W, t0):
    t = np.concatenate([r.t for r in runs])
    lo = t.min() if t0 is None else t0
    edges = np.linspace(lo, t.max(), W + 1)
    edges[-1] += 1e-12*max(1.0, abs(edges[-1]))
    return edges


def statistics(r, edges, B, classEdges):
    """{name: array of B batch values (nan: no data)} and overall values."""
    batch = r.id % B
    out = {}
    overall = {}
    names = 'xyz'

    def put(name, perBatch, allValue):
        out[name] = np.array(perBatch, dtype=float)
        overall[name] = allValue

    # Orientation of the fibers in the domain per time window
    for w in range(len(edges) - 1):
        sel = (r.t >= edges[w]) & (r.t < edges[w + 1])
        for k in range(3):
            a = np.abs(r.p[sel, k])
            q = r.p[sel, k]**2
            b = batch[sel]
            put('absP.%s.w%d' % (names[k], w),
                [a[b == j].mean() if (b == j).any() else np.nan
                 for j in range(B)], a.mean() if a.size else np.nan)
            put('pp.%s%s.w%d' % (names[k], names[k], w),
                [q[b == j].mean() if (b == j).any() else np.nan
                 for j in range(B)], q.mean() if q.size else np.nan)

    if not r.injected:
        return out, overall

    # Fates per fiber: outlet, deposited or in the domain
    ids = np.array(sorted(r.injected))
    L = np.array([r.injected[i][1] for i in ids])
    fate = []
    for i in ids:
        if i in r.left:
            t, kind, patch, p = r.left[i]
            fate.append(patch if kind == 'escaped' else 'deposited')
        else:
            fate.append('inDomain')
    fate = np.array(fate)
    bId = ids % B
    outcomes = sorted(set(fate) | {'deposited', 'inDomain'})
    classes = [('', np.ones(len(ids), bool))]
    if classEdges is not None:
        for c in range(len(classEdges) - 1):
            lo, hi = classEdges[c], classEdges[c + 1]
            sel = (L >= lo) & ((L < hi) if c < len(classEdges) - 2
                               else (L <= hi))
            classes.append(('.L%d' % c, sel))
    for o in outcomes:
        for cname, sel in classes:
            x = (fate == o).astype(float)
            put('fate.%s%s' % (o, cname),
                [x[sel & (bId == j)].mean() if (sel & (bId == j)).any()
                 else np.nan for j in range(B)],
                x[sel].mean() if sel.any() else np.nan)

    # At the escape: orientation and residence time per outlet
    for o in outcomes:
        if o in ('deposited', 'inDomain'):
            continue
        eid = np.array([i for i in ids if i in r.left
                        and r.left[i][1] == 'escaped' and r.left[i][2] == o])
        if eid.size == 0:
            continue
        p = np.array([np.abs(r.left[i][3]) for i in eid])
        res = np.array([r.left[i][0] - r.injected[i][0] for i in eid])
        eb = eid % B
        for k in range(3):
            put('escapeAbsP.%s.%s' % (o, names[k]),
                [p[eb == j, k].mean() if (eb == j).any() else np.nan
                 for j in range(B)], p[:, k].mean())
        for qn, q in (('median', 50), ('p90', 90)):
            put('residence.%s.%s' % (o, qn),
                [np.percentile(res[eb == j], q) if (eb == j).sum() >= 3
                 else np.nan for j in range(B)], np.percentile(res, q))
    return out, overall


def lengthClasses(r):
    if not r.injected:
        return None
    L = np.array([v[1] for v in r.injected.values()])
    if L.max() - L.min() <= 1e-9*L.max():
        return None
    return np.linspace(L.min(), L.max(), 4)


def se(values, B):
    v = values[~np.isnan(values)]
    if v.size < max(2, B//2):
        return np.nan
    return v.std(ddof=1)/math.sqrt(v.size)


def options(args):
    opt = {'-windows': 5, '-batches': 20, '-t0': None, '-z': 3.0,
           '-label': '', '-table': None}
    pos = []
    k = 0
    while k < len(args):
        if args[k] in opt:
            v = args[k + 1]
            opt[args[k]] = (v if args[k] in ('-label', '-table')
                            else float(v))
            k += 2
        else:
            pos.append(args[k])
            k += 1
    opt['-windows'] = int(opt['-windows'])
    opt['-batches'] = int(opt['-batches'])
    return pos, opt


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ('stats', 'compare'):
        sys.exit(__doc__ or 'usage: see the header of ' + sys.argv[0])
    mode = sys.argv[1]
    pos, opt = options(sys.argv[2:])
    B, W = opt['-batches'], opt['-windows']
    runs = [Run(d) for d in pos]
    edges = windows(runs, W, opt['-t0'])
    classes = lengthClasses(runs[-1])
    stats = [statistics(r, edges, B, classes) for r in runs]

    if mode == 'stats':
        per, allv = stats[0]
        print('# statistic value standardError (batch means, B = %d)' % B)
        for n in per:
            print('%-32s %12.6g %12.4g' % (n, allv[n], se(per[n], B)))
        return

    (pj, aj), (pr, ar) = stats
    Z = opt['-z']
    rows = []
    nPass = nFail = nPaired = 0
    dPaired = 0.0
    for n in pr:
        if n not in pj:
            continue
        sj, sr = se(pj[n], B), se(pr[n], B)
        sp = se(pj[n] - pr[n], B)
        if np.isnan(sj) or np.isnan(sr) or np.isnan(aj[n]) \
                or np.isnan(ar[n]) \
                or (n.split('.')[0] in ('absP', 'pp', 'escapeAbsP')
                    and max(abs(aj[n]), abs(ar[n])) < 1e-9):
            # no data, or a direction the fibers do not have (2-D)
            rows.append((n, aj[n], ar[n], np.nan, sj, sr, np.nan, np.nan,
                         np.nan, np.nan, 'n/a'))
            continue
        d = aj[n] - ar[n]
        sc = math.sqrt(sj**2 + sr**2)
        z = d/sc if sc > 0 else (0.0 if d == 0 else np.inf)
        zp = d/sp if sp > 0 else (0.0 if d == 0 else np.inf)
        ok = abs(z) <= Z
        nPass += ok
        nFail += not ok
        if abs(zp) > Z:
            nPaired += 1
            dPaired = max(dPaired, abs(d))
        rows.append((n, aj[n], ar[n], d, sj, sr, sc, sp, z, zp,
                     'PASS' if ok else 'FAIL'))
    head = ('# %s statistic judged reference difference seJudged seRef'
            ' seCombined sePaired z zPaired verdict' % opt['-label']).replace(
                '#  ', '# ')
    lines = [head]
    for r in rows:
        lines.append('%-34s %11.5g %11.5g %11.3g %10.3g %10.3g %10.3g '
                     '%10.3g %7.2f %7.2f %s' % r)
    lines.append('# %d pass, %d fail (|difference| <= %g combined standard'
                 ' errors), batches %d, windows %d; paired: %d beyond %g'
                 ' paired standard errors, the largest of their differences'
                 ' %.3g' % (nPass, nFail, Z, B, W, nPaired, Z, dPaired))
    text = '\n'.join(lines)
    print(text)
    if opt['-table']:
        with open(opt['-table'], 'a') as f:
            for line in lines[1:-1]:
                f.write((opt['-label'] + ' ' + line).strip() + '\n')
    sys.exit(0 if nFail == 0 else 1)


if __name__ == '__main__':
    main()
