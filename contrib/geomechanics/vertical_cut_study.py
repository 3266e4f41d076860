#!/usr/bin/python3
"""Vertical cut in undrained clay: stands below H_c, collapses above.

    /usr/bin/python3 contrib/geomechanics/vertical_cut_study.py
        [--exe build/psmpm] [--work DIR] [--ratios 0.7,0.9,1.0,1.1,1.3]
        [--bases linear,powell-sabin] [--end-time 2] [--k0] [--jobs 1]
        [--reuse] [--no-files]

Runs prm/vertical_cut.prm (H = 1 m, rho = 2000 kg/m^3, g = 9.81 m/s^2,
Tresca soil with E / c_u = 750) for each H / H_c = r in --ratios, with
c_u = rho g H / (3.78 r) and E = 750 c_u (so that r is the only parameter
that changes), with each basis: linear with the lumped mass matrix of the
scene, powell-sabin with its defaults (Mass matrix/Type = automatic).
Prints a table and writes doc/data/vertical_cut.tsv and
doc/images/vertical_cut.png (the face's displacement x_max - x_max(0)
over H against t / sqrt(H/g)).

Measured per run (from statistics.txt, summary.json and the particle VTU
written at T/2 and T): u_top, the horizontal displacement of the
particle that starts nearest the top of the face (2, 1), at T/2 and at
the end T; v_top its
vertical displacement (the crest's settlement); the run-out x_max(T) -
x_max(0) of the soil (the face's bulge while it stands) and its largest
value over the run (runout_peak: with the dynamic overshoot); the plastic
dissipation D at T/2 and T, the kinetic energy at T and the drift of the
total energy (kinetic + strain + gravity + dissipated) E(T) - E(0), all
over rho g H^3 (J per m of thickness); steps, CPU and wall seconds.

--k0 adds the effect of the initial stress at r = 0.7 and 1.0 (linear):
K0 = 1 (the scene), K0 = nu / (1 - nu) = 0.43 and Stress = none (gravity
switched on at t = 0).

Needs python3-numpy and python3-matplotlib (Debian).
"""
import argparse
import concurrent.futures
import json
import os
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "lib"))
from psmpm_output import ROOT, vtu_arrays  # noqa: E402
from psmpm_output import read_statistics as statistics  # noqa: E402
RHO, G, H, NC, E_OVER_C = 2000.0, 9.81, 1.0, 3.78, 750.0
GAMMA_H3 = RHO * G * H ** 3
FACE_TOP = (2.0, 1.0)


def overrides(ratio, basis, end_time, extra=()):
    c_u = RHO * G * H / (NC * ratio)
    sets = ['Material/Cohesion=%.6g' % c_u,
            "Material/Young's modulus=%.6g" % (E_OVER_C * c_u),
            'Basis/Type=' + basis, 'Time/End time=%g' % end_time,
            # Particle output at T/2 and T (and t = 0).
            'Output/Interval=0', 'Output/Time interval=%g' % (end_time / 2)]
    if basis == 'powell-sabin':
        sets.append('Mass matrix/Type=automatic')
    return sets + list(extra)


def run(exe, work, tag, sets, reuse=False):
    d = os.path.join(work, tag)
    if reuse and os.path.exists(os.path.join(d, 'summary.json')):
        return evaluate(d, 0)
    args = [exe, os.path.join(ROOT, 'prm', 'vertical_cut.prm'),
            '--set', 'Output directory=' + d]
    for s in sets:
        args += ['--set', s]
    p = subprocess.run(args, capture_output=True, text=True)
    if p.returncode != 0:
        sys.stderr.write('%s: exit code %d\n%s' % (tag, p.returncode,
                                                   p.stdout[-2000:]))
    return evaluate(d, p.returncode)


def evaluate(d, returncode):
    summary = json.load(open(os.path.join(d, 'summary.json')))
    s = statistics(os.path.join(d, 'statistics.txt'))
    steps = sorted(int(f[10:15]) for f in os.listdir(d)
                   if f.startswith('particles-') and f.endswith('.000.vtu'))
    top = []
    for step in steps:
        a = vtu_arrays(os.path.join(d, 'particles-%05d.000.vtu' % step))
        u = a['displacement'][:, :2]
        X = a['Points'][:, :2] - u
        i = np.argmin(np.hypot(X[:, 0] - FACE_TOP[0], X[:, 1] - FACE_TOP[1]))
        top.append(u[i])
    e = s['total_energy']
    k = s['kinetic_energy']
    half = len(k) // 2
    return {
        'status': summary['status'], 'exit': returncode,
        'u_top_half': top[len(top) // 2][0] / H if len(top) > 2 else np.nan,
        'u_top': top[-1][0] / H, 'v_top': top[-1][1] / H,
        'runout': (s['body1_x_max'][-1] - s['body1_x_max'][0]) / H,
        'runout_peak': (s['body1_x_max'].max() - s['body1_x_max'][0]) / H,
        'dissipated': s['dissipated_energy'][-1] / GAMMA_H3,
        'dissipated_half': s['dissipated_energy'][half] / GAMMA_H3,
        'kinetic_max': k.max() / GAMMA_H3,
        'kinetic_end': k[-1] / GAMMA_H3,
        'drift': (e[-1] - e[0]) / GAMMA_H3,
        'cpu_s': summary['cpu_time_s'], 'wall_s': summary['wall_time_s'],
        'steps': summary['steps'],
        'time': s['time'], 'x_max': s['body1_x_max'] - s['body1_x_max'][0],
    }


COLUMNS = [('u_top_half', '%.4f'), ('u_top', '%.4f'), ('v_top', '%.4f'),
           ('runout_peak', '%.4f'), ('runout', '%.4f'),
           ('dissipated_half', '%.4g'), ('dissipated', '%.4g'),
           ('kinetic_end', '%.3g'), ('drift', '%.2g'),
           ('steps', '%d'), ('cpu_s', '%.1f'), ('wall_s', '%.1f')]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--exe', default=os.path.join(ROOT, 'build', 'psmpm'))
    ap.add_argument('--work', default='vertical-cut-study')
    ap.add_argument('--ratios', default='0.7,0.9,1.0,1.1,1.3')
    ap.add_argument('--bases', default='linear,powell-sabin')
    ap.add_argument('--end-time', type=float, default=2.0)
    ap.add_argument('--k0', action='store_true')
    ap.add_argument('--jobs', type=int, default=1)
    ap.add_argument('--reuse', action='store_true',
                    help='evaluate the runs already in --work (same '
                    'options) instead of running them again')
    ap.add_argument('--no-files', action='store_true',
                    help='print only; do not write doc/data, doc/images')
    args = ap.parse_args()
    ratios = [float(r) for r in args.ratios.split(',')]
    bases = args.bases.split(',')
    jobs = [(b, r, 'K0 = 1', []) for b in bases for r in ratios]
    if args.k0:
        for r in (0.7, 1.0):
            jobs.append(('linear', r, 'K0 = 0.43',
                         ['Initial conditions/K0=0.428571']))
            jobs.append(('linear', r, 'stress-free',
                         ['Initial conditions/Stress=none']))
    os.makedirs(args.work, exist_ok=True)
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(run, args.exe, args.work,
                               '%s-%g-%s' % (b, r, re.sub(r'\W+', '', k)),
                               overrides(r, b, args.end_time, extra),
                               args.reuse)
                   for b, r, k, extra in jobs]
        results = [f.result() for f in futures]

    header = ['basis', 'H/H_c', 'initial stress', 'status'] + \
        [c for c, _ in COLUMNS]
    lines = ['\t'.join(header)]
    for (b, r, k, _), res in zip(jobs, results):
        lines.append('\t'.join([b, '%g' % r, k, res['status']] +
                               [f % res[c] for c, f in COLUMNS]))
    print('# T = %g s = %.1f sqrt(H/g); u_top, v_top, runout over H; '
          'dissipated, kinetic_end, drift over rho g H^3 = %g J'
          % (args.end_time, args.end_time / np.sqrt(H / G), GAMMA_H3))
    print('\n'.join(lines))
    if args.no_files:
        return
    os.makedirs(os.path.join(ROOT, 'doc', 'data'), exist_ok=True)
    with open(os.path.join(ROOT, 'doc', 'data', 'vertical_cut.tsv'),
              'w') as f:
        f.write('# contrib/geomechanics/vertical_cut_study.py: '
                'prm/vertical_cut.prm, T = %g s\n' % args.end_time)
        f.write('\n'.join(lines) + '\n')

    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(bases), figsize=(5.5 * len(bases), 4),
                             sharey=True, squeeze=False)
    for ax, b in zip(axes[0], bases):
        for (bb, r, k, _), res in zip(jobs, results):
            if bb == b and k == 'K0 = 1':
                ax.plot(res['time'] / np.sqrt(H / G), res['x_max'] / H,
                        label='H/H_c = %g' % r)
        ax.set_yscale('symlog', linthresh=1e-3)
        ax.set_xlabel('t / sqrt(H/g)')
        ax.set_title(b)
        ax.grid(True, alpha=0.3)
    axes[0][0].set_ylabel('face displacement (x_max - x_max(0)) / H')
    axes[0][-1].legend(loc='lower right', ncol=3, fontsize='small')
    fig.tight_layout()
    os.makedirs(os.path.join(ROOT, 'doc', 'images'), exist_ok=True)
    fig.savefig(os.path.join(ROOT, 'doc', 'images', 'vertical_cut.png'),
                dpi=110)


if __name__ == '__main__':
    main()
