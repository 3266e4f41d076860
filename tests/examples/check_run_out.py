#!/usr/bin/python3
"""Check the run-out postprocessor of examples/custom_postprocessor.

  check_run_out.py SPEED TOLERANCE EXECUTABLE SCENE OUTPUT_DIRECTORY

The scene moves a body at a constant velocity v without stress, so its
front along the unit direction d advances at SPEED = v . d: column run_out
of OUTPUT_DIRECTORY/statistics.txt must be SPEED * time in every row and
run_out of summary.json SPEED * end time, each within TOLERANCE (m).
Then a zero Run-out/Direction must be refused as bad input: exit code 2,
a message naming the entry, its value and the scene file, no output.
"""
import json
import math
import os
import subprocess
import sys
import tempfile


def columns(path):
    """The columns of statistics.txt by name (rows of numbers only)."""
    names, rows = [], []
    with open(path) as f:
        for line in f:
            if line.startswith('#'):
                # "# j: name"
                names.append(line.split(':', 1)[1].strip())
            elif line.strip():
                rows.append(line.split())
    if not rows or any(len(r) != len(names) for r in rows):
        sys.exit(f'FAIL: {path}: {len(rows)} rows, not all of '
                 f'{len(names)} columns')
    return {n: [float(r[j]) for r in rows] for j, n in enumerate(names)}


def check_values(speed, tolerance, output):
    table = columns(os.path.join(output, 'statistics.txt'))
    if 'run_out' not in table:
        sys.exit(f'FAIL: no column run_out in {output}/statistics.txt: '
                 f'{sorted(table)}')
    time, run_out = table['time'], table['run_out']
    errors = [abs(r - speed * t) for t, r in zip(time, run_out)]
    worst = max(range(len(errors)), key=errors.__getitem__)
    print(f'run_out: {len(run_out)} rows, largest |run_out - {speed} t| = '
          f'{errors[worst]:.3e} at t = {time[worst]}')
    if not (len(run_out) > 1 and time[-1] > 0 and errors[worst] <= tolerance):
        sys.exit(f'FAIL: run_out = {run_out[worst]} at t = {time[worst]}, '
                 f'expected {speed * time[worst]} (tolerance {tolerance})')
    with open(os.path.join(output, 'summary.json')) as f:
        summary = json.load(f)
    expected = speed * summary['end_time']
    final = summary.get('run_out', math.nan)
    print(f'summary.json: run_out = {final}, expected {expected}')
    if not abs(final - expected) <= tolerance:
        sys.exit(f'FAIL: summary.json run_out = {final}, expected {expected}')


def check_bad_direction(executable, scene):
    with tempfile.TemporaryDirectory() as work:
        run = subprocess.run([executable, scene, '--set',
                              'Run-out/Direction=0, 0',
                              '--set', 'Output directory=bad'],
                             cwd=work, capture_output=True, text=True)
        message = run.stdout + run.stderr
        print(f'Run-out/Direction = 0, 0: exit code {run.returncode}')
        if (run.returncode != 2 or 'Run-out/Direction' not in message
                or os.path.basename(scene) not in message):
            sys.exit('FAIL: a zero Run-out/Direction must exit with 2 and '
                     'name the entry and the file:\n' + message)
        if os.path.exists(os.path.join(work, 'bad')):
            sys.exit('FAIL: bad input left an output directory')


def main():
    speed, tolerance = float(sys.argv[1]), float(sys.argv[2])
    executable, scene, output = map(os.path.abspath, sys.argv[3:6])
    check_values(speed, tolerance, output)
    check_bad_direction(executable, scene)
    print('OK: run_out matches the closed form')


if __name__ == '__main__':
    main()
