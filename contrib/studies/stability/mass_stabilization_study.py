#!/usr/bin/python3
"""Mass strategies on the rotating block, the spreading block and the PS
vibrating bar (doc/stability.md, "Stabilised consistent mass").

usage: contrib/studies/stability/mass_stabilization_study.py BUILD/psmpm OUTDIR [filter]
Writes OUTDIR/mass_stabilization.tsv: scene, basis, transfer, mass,
status, reason, failed time, steps, error, CPU s (user+sys), wall s, CG
iterations, largest CG condition estimate. For the rotating block the
"error" is the rotation angle (Procrustes fit of the final particle
positions to the initial ones) over pi/2, for the bar the summary's
displacement error at the end time.
"""
import json, math, os, re, subprocess, sys


sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "lib"))
from psmpm_output import ROOT, vtu_arrays  # noqa: E402


def rotation_angle(directory):
    if not os.path.isdir(directory):
        return float('nan')
    files = sorted(f for f in os.listdir(directory)
                   if f.startswith('particles-') and f.endswith('.000.vtu'))
    if not files:
        return float('nan')
    a = vtu_arrays(os.path.join(directory, files[-1]))
    x = [p[:2] for p in a['Points']]
    x0 = [(p[0] - u[0], p[1] - u[1]) for p, u in zip(x, a['displacement'])]
    m = list(a['mass'])
    M = sum(m)

    def centred(y):
        c = [sum(mi * yi[k] for mi, yi in zip(m, y)) / M for k in (0, 1)]
        return [(yi[0] - c[0], yi[1] - c[1]) for yi in y]
    x, x0 = centred(x), centred(x0)
    cross = sum(mi * (a0[0] * b[1] - a0[1] * b[0])
                for mi, a0, b in zip(m, x0, x))
    dot = sum(mi * (a0[0] * b[0] + a0[1] * b[1])
              for mi, a0, b in zip(m, x0, x))
    return math.atan2(cross, dot)


def run(exe, outdir, tag, prm, sets):
    d = os.path.join(outdir, tag)
    args = [exe, os.path.join(ROOT, 'prm', prm), '--set',
            'Output directory=' + d]
    for s in sets:
        args += ['--set', s]
    p = subprocess.run(['/usr/bin/time', '-v'] + args, capture_output=True,
                       text=True)
    t = p.stderr
    cpu = (float(re.search(r'User time \(seconds\): ([\d.]+)', t).group(1)) +
           float(re.search(r'System time \(seconds\): ([\d.]+)', t).group(1)))
    w = re.search(r'Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):([\d.]+)', t)
    wall = (int(w.group(1) or 0) * 3600 + int(w.group(2)) * 60 +
            float(w.group(3)))
    try:
        s = json.load(open(os.path.join(d, 'summary.json')))
    except Exception:
        s = {'status': 'error', 'reason': p.stderr.strip()[-200:]}
    cond = 0.
    try:
        for line in open(os.path.join(d, 'statistics.txt')):
            if not line.startswith('#') and line.strip():
                cond = max(cond, float(line.split()[11]))
    except Exception:
        pass
    return d, s, cpu, wall, cond


SCENES = {
    # name: (prm, sets, end-time override)
    'rotating block': ('rotating_block.prm', [
        'Output/Interval=100000', 'Stability/Energy tolerance=0.1']),
    'spreading block': ('spreading_block.prm', [
        'Output/Interval=100000', 'Time/Courant number=0.5']),
    'vibrating bar 8': ('vibrating_bar_small_ps.prm', [
        'Mesh/Blocks x=8', 'Output/Interval=100000']),
}


def main():
    exe, outdir = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    pattern = re.compile(sys.argv[3]) if len(sys.argv) > 3 else None
    masses = os.environ.get('MASSES', 'consistent|partially lumped|lumped|'
                            'ghost penalty|blended lumping|'
                            'fictitious mass').split('|')
    bases = os.environ.get('BASES', 'linear|powell-sabin').split('|')
    transfers = os.environ.get('TRANSFERS', 'musl|apic').split('|')
    os.makedirs(outdir, exist_ok=True)
    tsv = open(os.path.join(outdir, 'mass_stabilization.tsv'), 'a')
    for scene, (prm, sets) in SCENES.items():
        for basis in bases:
            if scene == 'spreading block' and basis != 'powell-sabin':
                continue
            if scene.startswith('vibrating bar') and basis != 'powell-sabin':
                continue
            for transfer in transfers:
                for mass in masses:
                    tag = '_'.join(x.replace(' ', '-') for x in
                                   (scene, basis, transfer, mass))
                    if pattern and not pattern.search(tag):
                        continue
                    extra = ['Basis/Type=' + basis, 'Mass matrix/Type=' + mass]
                    if transfer != 'musl':
                        extra.append('Transfer/Scheme=' + transfer)
                    d, s, cpu, wall, cond = run(exe, outdir, tag, prm,
                                                sets + extra)
                    if scene == 'rotating block':
                        err = 'angle/(pi/2) = %.4f' % (rotation_angle(d) /
                                                       (math.pi / 2))
                    elif scene.startswith('vibrating'):
                        e = s.get('errors', {})
                        err = 'E_u = %.4g' % e.get('displacement_L2',
                                                   float('nan'))
                    else:
                        err = '-'
                    row = [scene, basis, transfer, mass, s.get('status'),
                           str(s.get('reason', ''))[:80],
                           str(s.get('failed_time', '')),
                           str(s.get('steps', '')), err, '%.2f' % cpu,
                           '%.2f' % wall, str(s.get('cg_iterations', '')),
                           '%.3g' % cond]
                    print('\t'.join(row), flush=True)
                    tsv.write('\t'.join(row) + '\n')
                    tsv.flush()


if __name__ == '__main__':
    main()
