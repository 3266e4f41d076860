#!/usr/bin/python3
"""P1 with the automatic mass matrix on sparse particle layouts.

Runs the free-body scenes of prm/ (column collapse, two disks, ring impact,
rotating block, neo-Hookean spreading block) with Basis/Type = linear,
Mass matrix/Type = automatic and Transfer/Scheme = automatic, each with
the particles per block of LAYOUTS (default 1x1 2x1 2x2 3x2 3x3 4x4 and
the scene's own), and prints one row per run: status, steps, the reason if
unstable, the relative change of the angular momentum, the largest rise of
the total energy above its start relative to the energy scale of the
run, and the CPU seconds (summary.json cpu_time_s).

    /usr/bin/python3 contrib/studies/stability/sparse_p1_layouts.py BINARY [OUT.tsv]

Environment: LAYOUTS="2x2 2x1", SCENES="two_disks column_collapse",
EXTRA="Section/Name=value;..." (more --set overrides for every run).
doc/stability.md, "Sampling of P1 cells", quotes its table.
"""
import json, os, subprocess, sys, tempfile

here = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
binary = sys.argv[1]
out_tsv = sys.argv[2] if len(sys.argv) > 2 else None
scenes = os.environ.get(
    "SCENES",
    "column_collapse two_disks ring_impact rotating_block "
    "spreading_block_neo_hookean").split()
layouts = os.environ.get("LAYOUTS", "1x1 2x1 2x2 3x2 3x3 4x4 own").split()
extra = [e for e in os.environ.get("EXTRA", "").split(";") if e]

def column(path, name):
    names, rows = [], []
    for line in open(path):
        if line.startswith("# ") and ": " in line:
            names.append(line.split(": ", 1)[1].strip())
        elif line.strip() and not line.startswith("#"):
            rows.append(line.split())
    if name not in names:
        return []
    i = names.index(name)
    return [float(r[i]) for r in rows]

rows = []
work = tempfile.mkdtemp()
for scene in scenes:
    for layout in layouts:
        sets = ["Basis/Type=linear", "Mass matrix/Type=automatic",
                "Transfer/Scheme=automatic", "Output/Interval=0",
                f"Output directory={work}/run"] + extra
        if layout != "own":
            px, py = layout.split("x")
            sets += [f"Particles/Per block x={px}", f"Particles/Per block y={py}"]
        args = [binary, os.path.join(here, "prm", scene + ".prm")]
        for s in sets:
            args += ["--set", s]
        code = subprocess.run(args, stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL).returncode
        try:
            d = json.load(open(f"{work}/run/summary.json"))
        except OSError:
            rows.append((scene, layout, code, "no summary", "", "", "", "", ""))
            continue
        e = column(f"{work}/run/statistics.txt", "total_energy")
        k = column(f"{work}/run/statistics.txt", "kinetic_energy")
        s = column(f"{work}/run/statistics.txt", "strain_energy")
        scale = max([abs(x) for x in e + k + s] + [1e-300])
        rise = (max(e) - e[0]) / scale if e else float("nan")
        rows.append((scene, layout, code, d["status"], d["steps"],
                     d.get("reason", "")[:70],
                     d.get("angular_momentum_relative_change", ""),
                     f"{rise:.3g}", f"{d['cpu_time_s']:.2f}"))
        print("\t".join(str(x) for x in rows[-1]), flush=True)
if out_tsv:
    with open(out_tsv, "w") as f:
        f.write("scene\tlayout\texit\tstatus\tsteps\treason\tangular_momentum_change\tenergy_rise\tcpu_s\n")
        for r in rows:
            f.write("\t".join(str(x) for x in r) + "\n")
bad = [r for r in rows if r[3] != "completed"]
print(f"{len(rows) - len(bad)} of {len(rows)} runs completed")
