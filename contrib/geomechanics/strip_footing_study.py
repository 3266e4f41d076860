#!/usr/bin/python3
"""Strip footing: the limit load against Prandtl's, per basis, mesh and soil.

    /usr/bin/python3 contrib/geomechanics/strip_footing_study.py
        [--exe build/psmpm] [--work DIR] [--meshes 4,8,16]
        [--bases linear,powell-sabin] [--cases tresca,tresca-nu45,
        cphi-psi0,cphi-assoc] [--jobs 1] [--reuse] [--no-files]
        [--references]
        [--body [--width 1] [--end-settlement 0.12]
         [--set Subsection/Entry=value ...]]

Runs prm/strip_footing.prm (rigid rough footing, B = 1 m, pushed down at
0.1 m/s into weightless soil; half model) on the criss-cross meshes of
contrib/geomechanics/make_strip_footing_mesh.py with --meshes blocks per
m (2, 4, 8 blocks under the half footing for 4, 8, 16), with each basis:
linear (lumped mass, MUSL) and powell-sabin (lumped mass, APIC; MUSL
grows unstable within 30 steps here). Cases:

    tresca       phi = 0, c_u = 10 kPa, E = 500 c_u, nu = 0.3:
                 q_u / c_u = 2 + pi = 5.142
    tresca-nu45  the same with nu = 0.45 (closer to undrained)
    cphi-psi0    phi = 20 deg, psi = 0, c = 10 kPa, E = 2000 c, nu = 0.3:
                 q_u / c = N_c = 14.835 (associated flow)
    cphi-assoc   the same with psi = phi = 20 deg

The load q = -2 reaction_footing_y / B (per m); the settlement s = the
integral of the prescribed velocity. q is averaged over settlement windows
of 0.01 B (the step-to-step load oscillates by a few %); the limit load
q_u is the largest window mean (the grid does not follow the footing: the
load falls once s exceeds about h/2, see doc/geomechanics.md). Prints a
table and writes doc/data/strip_footing.tsv and doc/images/
strip_footing.png (q/c against s/B with the reference lines).

With --body the footing is a driven body instead of a mesh boundary:
prm/strip_footing_body.prm (a criss-cross grid over [0, 5] x [0, 3] m,
--meshes blocks per m; the footing, Body 2, is the rectangle
[0, B/2] x [2.5, 2.75] driven down at the same velocity, in no-slip
contact with the soil). --width B changes the footing's width (the soil
domain stays); q = -2 contact_force_1_2_y / B. The footing's particles
move with it, so the run goes on to --end-settlement (0.12 B by default)
and the table adds the plateau: the mean of q/c over the last 0.02 B of
settlement (q_end, end_error against the reference), q_end / q_u
(hold: 1 if the load does not fall after its largest window) and the
mean of q/c over s = 0.045-0.055 B (q_05). --set
passes entries to every run (e.g. "Contact/Separation criterion=volume
fraction", or "Contact/Driven body nodes=geometry": the footing grips the
soil only at the nodes on or inside its moved outline). Files: doc/data/strip_footing_body.tsv and
doc/images/strip_footing_body.png (--no-files: none).

Needs python3-numpy and python3-matplotlib (Debian).
"""
import argparse
import concurrent.futures
import json
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_strip_footing_mesh  # noqa: E402
sys.path.insert(1, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "lib"))
from psmpm_output import read_statistics as statistics  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))
B, V0, RAMP, C = 1.0, 0.1, 0.1, 1e4
PHI = 20.0


def bearing_factor_nc(phi_deg):
    """Prandtl-Reissner N_c = (N_q - 1) cot phi (associated flow)."""
    t = math.tan(math.radians(phi_deg))
    nq = math.exp(math.pi * t) * math.tan(math.radians(45 + phi_deg / 2)) ** 2
    return (nq - 1) / t


NC = bearing_factor_nc(PHI)
CASES = {
    'tresca': (2 + math.pi, ['Material/Friction angle=0',
                             'Material/Dilatancy angle=0',
                             "Material/Young's modulus=5e6"]),
    'tresca-nu45': (2 + math.pi, ['Material/Friction angle=0',
                                  'Material/Dilatancy angle=0',
                                  "Material/Young's modulus=5e6",
                                  "Material/Poisson's ratio=0.45"]),
    'cphi-psi0': (NC, ['Material/Friction angle=%g' % PHI,
                       'Material/Dilatancy angle=0',
                       "Material/Young's modulus=2e7"]),
    'cphi-assoc': (NC, ['Material/Friction angle=%g' % PHI,
                        'Material/Dilatancy angle=%g' % PHI,
                        "Material/Young's modulus=2e7"]),
}


def davis_estimate(phi_deg, psi_deg):
    """q_u / c of a non-associated soil by Davis' reduced strength (Davis
    1968; Drescher and Detournay 1993): the associated limit load of c* =
    eta c and tan phi* = eta tan phi, eta = cos psi cos phi / (1 - sin psi
    sin phi). A lower estimate: the non-associated load lies between it
    and the associated one (eta = 1 for psi = phi)."""
    phi, psi = math.radians(phi_deg), math.radians(psi_deg)
    eta = math.cos(psi) * math.cos(phi) / (1 - math.sin(psi) * math.sin(phi))
    return eta * bearing_factor_nc(math.degrees(math.atan(eta * math.tan(phi))))


def print_references():
    """--references: each case's reference and, for c-phi, Davis'."""
    print('case\treference q_u/c\tDavis q_u/c\tDavis / reference - 1')
    for case, (ref, entries) in CASES.items():
        angles = dict(e.split('=') for e in entries if 'angle' in e)
        phi = float(angles['Material/Friction angle'])
        psi = float(angles['Material/Dilatancy angle'])
        # phi = 0 (Tresca): no friction to reduce, Davis' load is the
        # reference.
        davis = davis_estimate(phi, psi) if phi > 0 else ref
        print('%s\t%.3f\t%.3f\t%+.4f' % (case, ref, davis, davis / ref - 1))


END_TIME = 0.85   # settlement 0.08 B
WINDOW = 0.01     # B


def settlement(t):
    """Integral of v0 min(t / ramp, 1)."""
    return np.where(t < RAMP, V0 * t * t / (2 * RAMP), V0 * (t - RAMP / 2))


class Body:
    """The footing as a driven body (--body): width, end, extra entries;
    width None: the footing is the mesh boundary (prm/strip_footing.prm)."""
    width = None
    end_settlement = 0.12
    sets = []

    @staticmethod
    def end_time():
        """The time at which the settlement is end_settlement * width."""
        return Body.end_settlement * Body.width / V0 + RAMP / 2

    @staticmethod
    def entries(blocks):
        return ['Mesh/Blocks x=%d' % (5 * blocks),
                'Mesh/Blocks y=%d' % (3 * blocks),
                'Bodies/Body 2/Corners=0, 2.5, %g, 2.75' % (Body.width / 2),
                'Time/End time=%g' % Body.end_time()] + Body.sets


def run(exe, work, basis, blocks, case, reuse):
    tag = '%s-%d-%s' % (basis, blocks, case)
    d = os.path.join(work, tag)
    mesh = os.path.join(work, 'strip_footing_%d.msh' % blocks)
    if not (reuse and os.path.exists(os.path.join(d, 'summary.json'))):
        sets = ['Output directory=' + d, 'Basis/Type=' + basis,
                'Transfer/Scheme=' + ('apic' if basis == 'powell-sabin'
                                      else 'musl')] + CASES[case][1]
        if Body.width is None:
            sets += ['Mesh/File=' + mesh, 'Time/End time=%g' % END_TIME]
            scene = 'strip_footing.prm'
        else:
            sets += Body.entries(blocks)
            scene = 'strip_footing_body.prm'
        args = [exe, os.path.join(ROOT, 'prm', scene)]
        for s in sets:
            args += ['--set', s]
        p = subprocess.run(args, capture_output=True, text=True)
        if p.returncode != 0:
            sys.stderr.write('%s: exit code %d\n%s\n' % (
                tag, p.returncode, (p.stdout + p.stderr)[-600:]))
    return evaluate(d, basis, blocks, case)


def evaluate(d, basis, blocks, case):
    path = os.path.join(d, 'summary.json')
    if not os.path.exists(path):
        # No summary: the run stopped with an error (printed above).
        path = os.path.join(d, 'log.txt')
        summary = {'status': 'failed', 'n_particles': 0,
                   'cpu_time_s': np.nan, 'wall_time_s': np.nan, 'steps': 0}
    else:
        summary = json.load(open(path))
    s = statistics(os.path.join(d, 'statistics.txt'))
    t = s['time']
    width = B if Body.width is None else Body.width
    load = s['reaction_footing_y' if Body.width is None else
             'contact_force_1_2_y']
    work = s['prescribed_work' if Body.width is None else 'driven_work']
    q = -2 * load / width / C
    sb = settlement(t) / width
    # Window means of q over settlement windows of WINDOW B, sliding by
    # WINDOW / 4.
    best, at = -np.inf, 0.0
    lo = 0.0
    while lo + WINDOW <= sb[-1] + 1e-12:
        m = (sb >= lo) & (sb < lo + WINDOW)
        if m.any() and q[m].mean() > best:
            best, at = q[m].mean(), lo + WINDOW / 2
        lo += WINDOW / 4
    ref = CASES[case][0]
    floor = s['reaction_bottom_y']
    late = sb > 0.02
    end = sb > sb[-1] - 0.02
    mid = (sb >= 0.045) & (sb < 0.055)
    return {
        'basis': basis, 'blocks': blocks, 'case': case,
        'status': summary['status'], 'h': 1.0 / blocks,
        'under': int(round(blocks * width / 2)),
        'particles': summary['n_particles'],
        'qu': best, 'ref': ref, 'error': best / ref - 1, 'at': at,
        # Global equilibrium: footing load against the floor's reaction.
        'balance': np.mean(floor[late]) / -np.mean(load[late]) - 1
        if late.any() else np.nan,
        'q_05': np.mean(q[mid]) if mid.any() else np.nan,
        'q_end': np.mean(q[end]), 'hold': np.mean(q[end]) / best,
        'end_error': np.mean(q[end]) / ref - 1,
        'ke_over_w': s['kinetic_energy'].max() / work[-1],
        'cpu_s': summary['cpu_time_s'], 'wall_s': summary['wall_time_s'],
        'steps': summary['steps'], 's': sb, 'q': q,
    }


COLUMNS = [('status', '%s'), ('h', '%.4g'), ('under', '%d'),
           ('particles', '%d'), ('ref', '%.3f'), ('qu', '%.3f'),
           ('error', '%+.3f'), ('at', '%.3f'), ('balance', '%+.3f'),
           ('ke_over_w', '%.3g'), ('steps', '%d'), ('cpu_s', '%.1f'),
           ('wall_s', '%.1f')]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--exe', default=os.path.join(ROOT, 'build', 'psmpm'))
    ap.add_argument('--work', default='strip-footing-study')
    ap.add_argument('--meshes', default='4,8,16')
    ap.add_argument('--bases', default='linear,powell-sabin')
    ap.add_argument('--cases', default=','.join(CASES))
    ap.add_argument('--jobs', type=int, default=1)
    ap.add_argument('--references', action='store_true',
                    help="print each case's reference and Davis' "
                    'reduced-strength estimate for non-associated flow; '
                    'no runs')
    ap.add_argument('--reuse', action='store_true',
                    help='evaluate the runs already in --work instead of '
                    'running them again')
    ap.add_argument('--no-files', action='store_true',
                    help='print only; do not write doc/data, doc/images')
    ap.add_argument('--body', action='store_true',
                    help='the footing as a driven body '
                    '(prm/strip_footing_body.prm)')
    ap.add_argument('--width', type=float, default=B,
                    help='--body: the footing width B in m')
    ap.add_argument('--end-settlement', type=float,
                    default=Body.end_settlement,
                    help='--body: the last settlement / B')
    ap.add_argument('--set', action='append', default=[],
                    help='--body: an entry for every run')
    args = ap.parse_args()
    if args.references:
        print_references()
        return
    columns, name, end = COLUMNS, 'strip_footing', END_TIME
    if args.body:
        Body.width, Body.end_settlement = args.width, args.end_settlement
        Body.sets = args.set
        columns = COLUMNS[:7] + [('q_05', '%.3f'), ('q_end', '%.3f'),
                                 ('end_error', '%+.3f'),
                                 ('hold', '%.3f')] + COLUMNS[7:]
        name, end = 'strip_footing_body', Body.end_time()
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    meshes = [int(m) for m in args.meshes.split(',')]
    for m in meshes if not args.body else []:
        make_strip_footing_mesh.write_mesh(
            os.path.join(work, 'strip_footing_%d.msh' % m), m)
    jobs = [(b, m, c) for c in args.cases.split(',')
            for b in args.bases.split(',') for m in meshes]
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(run, args.exe, work, b, m, c, args.reuse)
                   for b, m, c in jobs]
        results = [f.result() for f in futures]

    header = ['case', 'basis', 'blocks_per_m'] + [c for c, _ in columns]
    lines = ['\t'.join(header)]
    for r in results:
        lines.append('\t'.join([r['case'], r['basis'], '%d' % r['blocks']] +
                               [f % r[c] for c, f in columns]))
    print('# q_u/c: largest mean of q/c over %g B of settlement; error = '
          'q_u / reference - 1; at: its settlement / B; balance: floor '
          'reaction / footing load - 1 (s > 0.02 B); ke_over_w: largest '
          'kinetic energy / the footing\'s work' % WINDOW)
    print('\n'.join(lines))
    if args.no_files:
        return
    os.makedirs(os.path.join(ROOT, 'doc', 'data'), exist_ok=True)
    with open(os.path.join(ROOT, 'doc', 'data', name + '.tsv'),
              'w') as f:
        f.write('# contrib/geomechanics/strip_footing_study.py%s: '
                'prm/%s.prm, settlement to %g B\n'
                % (' --body --width %g' % Body.width + ''.join(
                    ' --set "%s"' % e for e in Body.sets) if args.body
                   else '', name,
                   settlement(np.array([end]))[0] / (Body.width or B)))
        f.write('\n'.join(lines) + '\n')

    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    cases = list(dict.fromkeys(r['case'] for r in results))
    fig, axes = plt.subplots(1, len(cases), figsize=(4.6 * len(cases), 4),
                             squeeze=False)
    styles = {'linear': '-', 'powell-sabin': '--'}
    for ax, case in zip(axes[0], cases):
        for r in results:
            if r['case'] != case:
                continue
            # Smoothed over 0.005 B for legibility.
            k = max(1, int(len(r['s']) * 0.005 / max(r['s'][-1], 1e-9)))
            qs = np.convolve(r['q'], np.ones(k) / k, mode='valid')
            ax.plot(r['s'][k // 2:k // 2 + len(qs)], qs, styles.get(r['basis'], '-'),
                    label='%s, h = B/%d' % (r['basis'], r['blocks']))
        ref = CASES[case][0]
        ax.axhline(ref, color='k', lw=0.8)
        ax.axhspan(ref * 0.95, ref * 1.05, color='k', alpha=0.08)
        ax.set_xlabel('settlement / B')
        ax.set_title('%s (reference %.2f)' % (case, ref))
        ax.set_ylim(0, ref * 1.3)
        ax.grid(True, alpha=0.3)
    axes[0][0].set_ylabel('q / c')
    axes[0][0].legend(loc='lower right', fontsize='small')
    fig.tight_layout()
    os.makedirs(os.path.join(ROOT, 'doc', 'images'), exist_ok=True)
    fig.savefig(os.path.join(ROOT, 'doc', 'images', name + '.png'),
                dpi=110)


if __name__ == '__main__':
    main()
