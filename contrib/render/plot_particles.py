#!/usr/bin/python3
"""The particles of a psmpm run at several times, one panel above the
other, coloured by a field (matplotlib, no ParaView needed); the panels
show the box that holds every particle at every chosen time.

  contrib/render/plot_particles.py DIR FIELD MIN MAX OUT.png T1 [T2 ...]

FIELD is a particle field of particles.pvd ("velocity": its magnitude).
e.g. the README's picture:
  build/psmpm prm/granular_column_collapse.prm \\
    --set "Output directory=/tmp/gcc"
  contrib/render/plot_particles.py /tmp/gcc velocity 0 1.2 \\
    doc/images/granular_column_collapse.png 0 0.15 0.3 1
"""
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "lib"))
from psmpm_output import vtu_arrays  # noqa: E402


def series(directory):
    """[(time, [vtu files])] of particles.pvd (pieces of one output are
    read through their .pvtu's pieces)."""
    text = open(os.path.join(directory, "particles.pvd")).read()
    out = []
    for t, f in re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', text):
        path = os.path.join(directory, f)
        if path.endswith(".pvtu"):
            pieces = re.findall(r'<Piece Source="([^"]+)"', open(path).read())
            files = [os.path.join(os.path.dirname(path), p) for p in pieces]
        else:
            files = [path]
        out.append((float(t), files))
    return out


def particles(files, field):
    xs, vs = [], []
    for f in files:
        a = vtu_arrays(f)
        xs.append(a["Points"][:, :2])
        v = a[field]
        vs.append(np.linalg.norm(v, axis=1) if v.ndim > 1 else v)
    return np.concatenate(xs), np.concatenate(vs)


def main():
    directory, field = sys.argv[1], sys.argv[2]
    low, high, png = float(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
    wanted = [float(t) for t in sys.argv[6:]]
    available = series(directory)
    frames = []
    for t in wanted:
        time, files = min(available, key=lambda s: abs(s[0] - t))
        frames.append((time, *particles(files, field)))
    lo = np.min([x.min(axis=0) for _, x, _ in frames], axis=0)
    hi = np.max([x.max(axis=0) for _, x, _ in frames], axis=0)
    pad = 0.03 * (hi - lo).max()
    aspect = (hi[1] - lo[1] + 2 * pad) / (hi[0] - lo[0] + 2 * pad)
    fig, axes = plt.subplots(len(frames), 1, squeeze=False,
                             figsize=(9, len(frames) * (9 * aspect + 0.4)))
    for ax, (time, x, v) in zip(axes[:, 0], frames):
        sc = ax.scatter(x[:, 0], x[:, 1], c=v, s=1.5, vmin=low, vmax=high,
                        cmap="viridis", linewidths=0)
        ax.set_xlim(lo[0] - pad, hi[0] + pad)
        ax.set_ylim(lo[1] - pad, hi[1] + pad)
        ax.set_aspect("equal")
        ax.set_title(f"t = {time:.3g} s", fontsize=9)
        ax.tick_params(labelsize=7)
    fig.colorbar(sc, ax=axes[:, 0], shrink=0.8,
                 label="speed" if field == "velocity" else field)
    fig.savefig(png, dpi=110, bbox_inches="tight")
    print("wrote", png)


if __name__ == "__main__":
    main()
