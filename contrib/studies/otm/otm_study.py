#!/usr/bin/python3
"""OTM against MPM on the bar of Wobbes et al. (2019): doc/otm.md.

    /usr/bin/python3 contrib/studies/otm/otm_study.py [--exe build/psmpm] [--work DIR]
                                          [definitions] [crossing] [cost]
                                          [2d] [mass]

Every number comes from psmpm runs of prm/otm_bar_1d.prm (particle VTU
output, summary.json, /usr/bin/time); the script only evaluates them:

definitions  the 20-step stress RMS error under every definition and set-up
             detail tried against the paper's 3.8684 (OTM) / 3.8693 (MPM)
crossing     stress error over one period (grid crossing from t ~ 4 ms):
             RMS over all particles, near the left end (X < 0.1), the
             non-smooth part (residual of a least-squares fit of
             cos(j pi X / L), j = 0..6) and the number of local extrema
             of the stress along the bar;
             doc/otm_crossing.png, doc/otm_profile.png
cost         error against CPU time, 10 to 160 elements, t = 0.1 and 0.45;
             doc/otm_cost.png
2d           otm on 2D scenes (thesis bar, slumping block with P1, the
             tangling block with the automatic step)
mass         otm with each mass strategy that reads cell geometry, on the
             slumping block cut through cells

Needs python3-numpy and python3-matplotlib (Debian).
"""
import json
import math
import os
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "lib"))
from psmpm_output import ROOT, vtu_arrays  # noqa: E402
L, E, RHO, V0, DT = 1.0, 4e4, 2e3, 0.8, 1e-4
C = math.sqrt(E / RHO)
W = math.pi * C / L
K = math.pi / L
PAPER = {'otm': 3.8684, 'usl': 3.8693}


def particles(directory, step):
    """X (initial), x (current), stress_xx, volume, cell of one output."""
    a = vtu_arrays(os.path.join(directory,
                                'particles-%05d.000.vtu' % step))
    x = a['Points'][:, 0]
    u = a['displacement'] if a['displacement'].ndim == 1 else \
        a['displacement'][:, 0]
    s = a['stress_xx'] if 'stress_xx' in a else a['stress'][:, 0]
    order = np.argsort(x - u)
    return {'X': (x - u)[order], 'x': x[order], 's': s[order],
            'V': a['volume'][order], 'cell': a['cell'][order]}


def exact_stress(X, t, amplitude=V0 * math.sqrt(E * RHO), misprint=False):
    if misprint:  # eq. 40 as printed
        return amplitude * np.sin(W * t * np.cos(K * X))
    return amplitude * math.sin(W * t) * np.cos(K * X)


def run(exe, work, tag, sets, timed=False):
    d = os.path.join(work, tag)
    args = [exe, os.path.join(ROOT, 'prm', 'otm_bar_1d.prm'), '--set',
            'Output directory=' + d]
    for s in sets:
        args += ['--set', s]
    if timed:
        args = ['/usr/bin/time', '-f', 'CPU %U %S'] + args
    p = subprocess.run(args, capture_output=True, text=True)
    summary = json.load(open(os.path.join(d, 'summary.json')))
    if timed:
        u, s = re.search(r'CPU ([\d.]+) ([\d.]+)', p.stderr).groups()
        summary['cpu_s'] = float(u) + float(s)
    return d, summary


def output_steps(d):
    return sorted(int(f[10:15]) for f in os.listdir(d)
                  if f.startswith('particles-') and f.endswith('.000.vtu'))


# --------------------------------------------------------------------------
def definitions(exe, work):
    setups = [
        ('base: linear elastic, consistent, midpoints', []),
        ('hypoelastic (sigma += E de - de sigma)',
         ['Material/Model=hypoelastic']),
        ('lumped mass', ['Mass matrix/Type=lumped']),
    ]
    schemes = ['otm', 'usl', 'musl']
    rows = []
    for name, sets in setups:
        res = {}
        for scheme in schemes:
            d, _ = run(exe, work, 'def-%s-%d' % (scheme, len(rows)),
                       sets + ['Transfer/Scheme=' + scheme,
                               'Output/Interval=1'])
            steps = [particles(d, k) for k in range(21)]
            p = steps[20]
            t = 20 * DT
            e = {}
            dX = p['s'] - exact_stress(p['X'], t)
            e['natural: sqrt(mean_p d^2), exact at X_p, t_20'] = \
                np.sqrt(np.mean(dX ** 2))
            e['exact at current x_p'] = np.sqrt(np.mean(
                (p['s'] - exact_stress(p['x'], t)) ** 2))
            e['sqrt(sum_p V_p d^2) (psmpm stress_L2)'] = np.sqrt(
                np.sum(p['V'] * dX ** 2))
            e['sqrt(sum_p d^2)'] = np.sqrt(np.sum(dX ** 2))
            e['sqrt(sum_p d^2 / (N - 1))'] = np.sqrt(
                np.sum(dX ** 2) / (len(dX) - 1))
            e['exact at t_19 (one step behind)'] = np.sqrt(np.mean(
                (p['s'] - exact_stress(p['X'], t - DT)) ** 2))
            e['exact at t_20 - dt/2'] = np.sqrt(np.mean(
                (p['s'] - exact_stress(p['X'], t - DT / 2)) ** 2))
            e['amplitude 0.8 sqrt(E/rho) (eq. 40 as printed)'] = np.sqrt(
                np.mean((p['s'] - exact_stress(
                    p['X'], t, V0 * math.sqrt(E / RHO))) ** 2))
            e['eq. 40 as printed, amplitude and bracket'] = np.sqrt(
                np.mean((p['s'] - exact_stress(
                    p['X'], t, V0 * math.sqrt(E / RHO), True)) ** 2))
            e['bracket as printed, amplitude 0.8 sqrt(E rho)'] = np.sqrt(
                np.mean((p['s'] - exact_stress(p['X'], t,
                                               misprint=True)) ** 2))
            over = [np.mean((q['s'] - exact_stress(q['X'], k * DT)) ** 2)
                    for k, q in enumerate(steps)]
            e['RMS over particles and steps 1-20'] = np.sqrt(
                np.mean(over[1:]))
            e['RMS over particles and steps 0-20'] = np.sqrt(np.mean(over))
            e['RMS over steps 1-20, exact at current x_p'] = np.sqrt(np.mean(
                [np.mean((q['s'] - exact_stress(q['x'], k * DT)) ** 2)
                 for k, q in enumerate(steps) if k > 0]))
            e['RMS over steps 1-20 of sqrt(sum V d^2)'] = np.sqrt(np.mean(
                [np.sum(q['V'] * (q['s'] - exact_stress(q['X'], k * DT)) ** 2)
                 for k, q in enumerate(steps) if k > 0]))
            res[scheme] = e
        rows.append((name, res))
    print('\n### 20-step stress RMS error, every definition '
          '(paper: OTM 3.8684, MPM 3.8693)\n')
    print('| set-up | definition | otm | usl (paper MPM) | musl | '
          'otm - paper | usl - paper |')
    print('|---|---|---|---|---|---|---|')
    for name, res in rows:
        for key in res['otm']:
            o, u, m = (res[s][key] for s in schemes)
            print('| %s | %s | %.4f | %.4f | %.4f | %+.1f %% | %+.1f %% |' % (
                name, key, o, u, m, 100 * (o / PAPER['otm'] - 1),
                100 * (u / PAPER['usl'] - 1)))


# --------------------------------------------------------------------------
def crossing(exe, work):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    end, interval = 0.45, 10
    curves = {}
    profiles = {}
    snapshot = 0.25
    print('\n### After grid crossing (t = 0 to %g, one period 0.447 s)\n'
          % end)
    print('| scheme | first crossing t | RMS over time | RMS over time, '
          'X < 0.1 | non-smooth part over time | local extrema (mean) | '
          'max RMS | CPU s |')
    print('|---|---|---|---|---|---|---|---|')
    for scheme in ['otm', 'usl', 'musl', 'musl lumped', 'otm lumped']:
        sets = ['Mass matrix/Type=lumped'] if 'lumped' in scheme else []
        d, summary = run(exe, work, 'cross-' + scheme.replace(' ', '-'),
                         sets + ['Transfer/Scheme=' + scheme.split()[0],
                                 'Time/End time=%g' % end,
                                 'Output/Interval=%d' % interval],
                         timed=True)
        ts, rms, left, osc, changes = [], [], [], [], []
        first = None
        cell0 = None
        for k in output_steps(d):
            p = particles(d, k)
            t = k * DT
            if cell0 is None:
                cell0 = p['cell']
            elif first is None and np.any(p['cell'] != cell0):
                first = t
            dX = p['s'] - exact_stress(p['X'], t)
            # Oscillation part: what a smooth profile (the modes
            # cos(j pi X / L), j = 0..6) cannot represent.
            modes = np.cos(np.outer(p['X'], np.arange(7)) * K)
            coef = np.linalg.lstsq(modes, p['s'], rcond=None)[0]
            r = p['s'] - modes @ coef
            ts.append(t)
            rms.append(np.sqrt(np.mean(dX ** 2)))
            near = p['X'] < 0.1
            left.append(np.sqrt(np.mean(dX[near] ** 2)))
            osc.append(np.sqrt(np.mean(r ** 2)))
            # Local extrema of the stress along the bar (in X; equal
            # neighbours, OTM's constant element stress, do not count).
            ds = np.diff(p['s'])
            ds = ds[np.abs(ds) > 1e-9 * np.abs(p['s']).max()]
            changes.append(int(np.sum(np.sign(ds[1:]) != np.sign(ds[:-1]))))
            if abs(t - snapshot) < DT / 2:
                profiles[scheme] = (p['x'], p['s'], p['X'])
        ts, rms, left, osc = map(np.array, (ts, rms, left, osc))
        curves[scheme] = (ts, rms, left, osc, np.array(changes))
        print('| %s | %s | %.2f | %.2f | %.2f | %.1f | %.2f | %.2f |' % (
            scheme, '%.4f' % first if first is not None else 'none',
            np.sqrt(np.mean(rms ** 2)), np.sqrt(np.mean(left ** 2)),
            np.sqrt(np.mean(osc ** 2)), np.mean(changes), rms.max(),
            summary['cpu_s']))
    fig, ax = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    for scheme, (ts, rms, left, osc, _) in curves.items():
        ax[0].plot(ts, rms, label=scheme)
        ax[1].plot(ts, left, label=scheme)
        ax[2].plot(ts, osc, label=scheme)
    ax[0].set_ylabel('stress RMS error [Pa]')
    ax[1].set_ylabel('RMS error, X < 0.1 [Pa]')
    ax[2].set_ylabel('non-smooth part [Pa]')
    ax[2].set_xlabel('t [s]')
    ax[0].legend()
    ax[0].set_title('Bar of Wobbes et al. 2019: 20 P1 elements, 8 particles '
                    'each, dt = 1e-4')
    for a in ax:
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, 'doc', 'otm_crossing.png'), dpi=90)
    fig, ax = plt.subplots(figsize=(8, 4))
    for scheme, (x, s, X) in profiles.items():
        ax.plot(X, s, '.', ms=3, label=scheme)
    X = np.linspace(0, L, 200)
    ax.plot(X, exact_stress(X, snapshot), 'k-', lw=1, label='exact')
    ax.set_xlabel('initial position X [m]')
    ax.set_ylabel('stress [Pa]')
    ax.set_title('stress at t = %g s (cf. the paper\'s Figure 1)' % snapshot)
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, 'doc', 'otm_profile.png'), dpi=90)


# --------------------------------------------------------------------------
def cost(exe, work):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    print('\n### Error against CPU time (dt = 1e-4, 8 particles per '
          'element)\n')
    print('| end time | scheme | elements | stress RMS | displacement L2 | '
          'CPU s (process) | time loop s |')
    print('|---|---|---|---|---|---|---|')
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for i, end in enumerate([0.1, 0.45]):
        for scheme in ['otm', 'usl', 'musl']:
            pts = []
            for ne in [10, 20, 40, 80, 160]:
                d, s = run(exe, work, 'cost-%s-%d' % (scheme, ne),
                           ['Transfer/Scheme=' + scheme,
                            'Mesh/Blocks x=%d' % ne,
                            'Time/End time=%g' % end], timed=True)
                k = output_steps(d)[-1]
                p = particles(d, k)
                e = np.sqrt(np.mean(
                    (p['s'] - exact_stress(p['X'], k * DT)) ** 2))
                pts.append((s['time_loop_s'], e))
                print('| %g | %s | %d | %.3f | %.3e | %.2f | %.3f |' % (
                    end, scheme, ne, e,
                    s.get('errors', {}).get('displacement_L2', float('nan')),
                    s['cpu_s'], s['time_loop_s']))
            pts = np.array(pts)
            ax[i].loglog(pts[:, 0], pts[:, 1], 'o-', label=scheme)
        ax[i].set_xlabel('time loop [s]')
        ax[i].set_ylabel('stress RMS error at t = %g [Pa]' % end)
        ax[i].set_title('10 to 160 elements, t = %g' % end)
        ax[i].grid(alpha=0.3, which='both')
        ax[i].legend()
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, 'doc', 'otm_cost.png'), dpi=90)


# --------------------------------------------------------------------------
def two_d(exe, work):
    cases = [
        ('thesis bar (vibrating_bar_small.prm, 4 blocks)',
         'vibrating_bar_small.prm', []),
        ('thesis bar, 16 blocks', 'vibrating_bar_small.prm',
         ['Mesh/Blocks x=16']),
        ('slumping block, P1 lumped (spreading_block.prm)',
         'spreading_block.prm', ['Basis/Type=linear',
                                 'Mass matrix/Type=lumped',
                                 'Output/Interval=0']),
        ('slumping block, P1 partially lumped',
         'spreading_block.prm', ['Basis/Type=linear',
                                 'Mass matrix/Type=partially lumped',
                                 'Output/Interval=0']),
        ('tangling block, automatic step (otm_tangling.prm)',
         'otm_tangling.prm', ['Time/Time step=0']),
    ]
    print('\n### 2D scenes\n')
    print('| scene | scheme | status | steps | dt min | dt max | '
          'displacement L2 | reason | CPU s |')
    print('|---|---|---|---|---|---|---|---|---|')
    for name, prm, sets in cases:
        for scheme in ['otm', 'usl', 'musl']:
            d = os.path.join(work, '2d-' + scheme)
            args = ['/usr/bin/time', '-f', 'CPU %U %S', exe,
                    os.path.join(ROOT, 'prm', prm), '--set',
                    'Output directory=' + d, '--set',
                    'Transfer/Scheme=' + scheme] + \
                sum((['--set', s] for s in sets), [])
            p = subprocess.run(args, capture_output=True, text=True)
            s = json.load(open(os.path.join(d, 'summary.json')))
            u, y = re.search(r'CPU ([\d.]+) ([\d.]+)', p.stderr).groups()
            print('| %s | %s | %s | %d | %.3g | %.3g | %s | %s | %.1f |' % (
                name, scheme, s['status'], s['steps'],
                s['time_step_min'], s['time_step_max'],
                '%.3e' % s['errors']['displacement_L2']
                if 'errors' in s else '-',
                s.get('reason', '').replace('|', '/')[:90],
                float(u) + float(y)))


# --------------------------------------------------------------------------
def statistics_columns(path):
    """name -> list of values of statistics.txt (deal.II TableHandler)."""
    names, rows = [], []
    for line in open(path):
        if line.startswith('#'):
            names.append(line.split(':', 1)[1].strip() if ':' in line
                         else line[1:].strip())
        elif line.strip():
            rows.append(line.split())
    return {n: [r[i] for r in rows] for i, n in enumerate(names)}


def mass(exe, work):
    """otm with each mass strategy on the P1 slumping block cut through
    cells (Region 0.9 x 0.9: partly filled cells): whether what the
    strategies read of the initial cells stays constant, and how far the
    moved cells' areas (hence a fill measured on them) drift."""
    print('\n### Mass strategies with otm (slumping block, region 0.9 x '
          '0.9)\n')
    print('| Mass matrix/Type | status | steps | treated_dofs (distinct '
          'values) | min_relative_diagonal (min, max) | moved area / '
          'initial, occupied cells (min, max) | fill on moved cells '
          '(min, max over partly filled) |')
    print('|---|---|---|---|---|---|---|')
    for t in ['consistent', 'lumped', 'partially lumped', 'blended lumping',
              'fictitious mass', 'extrapolate']:
        d = os.path.join(work, 'mass-' + t.replace(' ', '_'))
        args = [exe, os.path.join(ROOT, 'prm', 'spreading_block.prm'),
                '--set', 'Output directory=' + d,
                '--set', 'Transfer/Scheme=otm',
                '--set', 'Basis/Type=linear',
                '--set', 'Mass matrix/Type=' + t,
                '--set', 'Particles/Region=0, 0, 0.9, 0.9',
                '--set', 'Output/Subdivisions=1',
                '--set', 'Output/Interval=1000000']
        subprocess.run(args, capture_output=True, text=True)
        s = json.load(open(os.path.join(d, 'summary.json')))
        c = statistics_columns(os.path.join(d, 'statistics.txt'))
        treated = sorted(set(int(float(v)) for v in c['treated_dofs'][1:]))
        rel = [float(v) for v in c['min_relative_diagonal'][1:]]
        last = max(int(f[5:10]) for f in os.listdir(d)
                   if f.startswith('grid-') and f.endswith('.000.vtu'))
        g = vtu_arrays(os.path.join(d, 'grid-%05d.000.vtu' % last))
        x = g['Points'][:, :2].reshape(-1, 3, 2)
        x0 = x - g['grid_displacement'][:, :2].reshape(-1, 3, 2)

        def area(v):
            return 0.5 * ((v[:, 1, 0] - v[:, 0, 0]) * (v[:, 2, 1] - v[:, 0, 1])
                          - (v[:, 2, 0] - v[:, 0, 0]) *
                          (v[:, 1, 1] - v[:, 0, 1]))
        p = vtu_arrays(os.path.join(d, 'particles-%05d.000.vtu' % last))
        cells = p['cell'].astype(int)
        m = np.bincount(cells, weights=p['mass'], minlength=len(x))
        occ = m > 0
        ratio = area(x)[occ] / area(x0)[occ]
        fill0 = m / (1000 * area(x0))
        fill = m / (1000 * area(x))
        part = occ & (fill0 < 1 - 1e-9)
        print('| %s | %s | %d | %s | %.4g, %.4g | %.3f, %.3f | %.3f, %.3f '
              '(initial cells %.3f, %.3f) |' % (
                  t, s['status'], s['steps'],
                  ', '.join(map(str, treated[:4])) +
                  (' ...' if len(treated) > 4 else ''),
                  min(rel), max(rel), ratio.min(), ratio.max(),
                  fill[part].min(), fill[part].max(),
                  fill0[part].min(), fill0[part].max()))


def main():
    args = sys.argv[1:]
    exe = os.path.join(ROOT, 'build', 'psmpm')
    work = '/tmp/psmpm-otm-study'
    if '--exe' in args:
        i = args.index('--exe')
        exe = os.path.abspath(args[i + 1])
        del args[i:i + 2]
    if '--work' in args:
        i = args.index('--work')
        work = args[i + 1]
        del args[i:i + 2]
    os.makedirs(work, exist_ok=True)
    parts = args or ['definitions', 'crossing', 'cost', '2d', 'mass']
    for part in parts:
        {'definitions': definitions, 'crossing': crossing, 'cost': cost,
         '2d': two_d, 'mass': mass}[part](exe, work)


if __name__ == '__main__':
    main()
