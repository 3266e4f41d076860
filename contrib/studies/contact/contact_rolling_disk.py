#!/usr/bin/python3
"""The rolling disk of prm/contact_rolling_disk.prm against its closed forms
(doc/contact.md, "With the defaults").

    /usr/bin/python3 contrib/studies/contact/contact_rolling_disk.py BINARY \
        [--cells 2 6 10] [--basis linear powell-sabin] [--mu 0.3] \
        [--theta 30] [--radius 0.1] [--end 0.1] [--set "A/B=c" ...]

Per run: the centre's acceleration a (a quadratic fit of body1_x over
t >= 0.02), against (2/3) g sin(theta) when mu >= tan(theta) / 3 (rolling)
and g (sin theta - mu cos theta) otherwise; from the particle output at
t_end / 2 and t_end, the disk's speed and spin (its particles' angular
momentum about their mass centre over their moment of inertia) at t_end,
spin R / speed, and the angular acceleration between the two outputs
against 2 mu g cos(theta) / R when it slips. Mesh: Mesh/Blocks x = 10 c,
y = 5 c for c cells per radius 0.1 (criss-cross, two triangles a block
edge); other radii scale the disk, not the mesh.
"""
import argparse
import glob
import math
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "lib"))
from psmpm_output import ROOT, vtu_arrays, read_statistics  # noqa: E402

import numpy as np  # noqa: E402

G = 9.81


def disk_state(step_file):
    """Speed (x velocity of the mass centre) and spin of body 1."""
    a = vtu_arrays(step_file)
    body = a['body_id'] == 1
    m = a['mass'][body]
    x = a['Points'][body, :2]
    v = a['velocity'][body, :2]
    xc = (m[:, None] * x).sum(0) / m.sum()
    vc = (m[:, None] * v).sum(0) / m.sum()
    r = x - xc
    w = v - vc
    L = (m * (r[:, 0] * w[:, 1] - r[:, 1] * w[:, 0])).sum()
    inertia = (m * (r * r).sum(1)).sum()
    return vc[0], L / inertia


def run(binary, basis, cells, mu, theta, radius, end, extra):
    t = math.radians(theta)
    out = tempfile.mkdtemp(prefix='rolling-')
    sets = {
        'Output directory': out,
        'Basis/Type': basis,
        'Mesh/Blocks x': str(10 * cells),
        'Mesh/Blocks y': str(5 * cells),
        'Time/End time': str(end),
        'Output/Interval': '0',
        'Output/Time interval': str(end / 2),
        'Contact/Friction coefficient': str(mu),
        'Body force/Gravity': '%.9g, %.9g' % (G * math.sin(t),
                                                -G * math.cos(t)),
        'Bodies/Body 1/Radius': str(radius),
        'Bodies/Body 1/Center': '0.25, %.9g' % (0.2 + radius),
    }
    cmd = [binary, os.path.join(ROOT, 'prm', 'contact_rolling_disk.prm')]
    for k, v in sets.items():
        cmd += ['--set', '%s=%s' % (k, v)]
    for s in extra:
        cmd += ['--set', s]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        shutil.rmtree(out, ignore_errors=True)
        return None, p.stdout[-500:] + p.stderr[-500:]
    s = read_statistics(os.path.join(out, 'statistics.txt'))
    keep = s['time'] >= 0.02
    c = np.polyfit(s['time'][keep], s['body1_x'][keep], 2)
    files = sorted(glob.glob(os.path.join(out, 'particles-*.000.vtu')))
    states = [disk_state(f) for f in files[-2:]]
    (v1, w1), (v2, w2) = states
    rolling = mu >= math.tan(t) / 3
    closed = (2. / 3 * G * math.sin(t) if rolling
              else G * (math.sin(t) - mu * math.cos(t)))
    shutil.rmtree(out)
    alpha = (w2 - w1) / (end / 2)
    alpha_closed = 0 if rolling else 2 * mu * G * math.cos(t) / radius
    return dict(a=2 * c[0], closed=closed, speed=v2, spinR=-w2 * radius,
                alpha=-alpha, alpha_closed=alpha_closed,
                rolling=rolling, steps=len(s['time'])), None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('binary')
    ap.add_argument('--cells', type=int, nargs='+', default=[2, 6, 10])
    ap.add_argument('--basis', nargs='+', default=['linear', 'powell-sabin'])
    ap.add_argument('--mu', type=float, default=0.3)
    ap.add_argument('--theta', type=float, default=30)
    ap.add_argument('--radius', type=float, default=0.1)
    ap.add_argument('--end', type=float, default=0.1)
    ap.add_argument('--set', action='append', default=[])
    args = ap.parse_args()
    for basis in args.basis:
        for cells in args.cells:
            r, err = run(args.binary, basis, cells, args.mu, args.theta,
                         args.radius, args.end, args.set)
            if r is None:
                print('%-13s %3d  failed: %s' % (basis, cells, err))
                continue
            line = ('%-13s %3d  a %.3f (closed %.3f, %+.2f %%)  speed %.4f  '
                    'spin R %.4f (%+.2f %% of speed)' %
                    (basis, cells, r['a'], r['closed'],
                     100 * (r['a'] / r['closed'] - 1), r['speed'],
                     r['spinR'], 100 * (r['spinR'] / r['speed'] - 1)))
            if not r['rolling']:
                line += '  alpha %.2f (closed %.2f, %+.2f %%)' % (
                    r['alpha'], r['alpha_closed'],
                    100 * (r['alpha'] / r['alpha_closed'] - 1))
            else:
                line += '  alpha R %.3f (%+.2f %% of a)' % (
                    r['alpha'] * args.radius,
                    100 * (r['alpha'] * args.radius / r['a'] - 1))
            print(line, flush=True)


if __name__ == '__main__':
    main()
