#!/usr/bin/python3
"""Energies and centre distance of the two-disk impact (prm/two_disks.prm)
against time, from the statistics.txt of one or more runs.

  contrib/render/plot_two_disks.py OUT.png DIR:LABEL [DIR:LABEL ...]
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "lib"))
from psmpm_output import read_statistics  # noqa: E402


def main():
    out = sys.argv[1]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4))
    for arg in sys.argv[2:]:
        directory, label = arg.split(":", 1)
        s = read_statistics(directory + "/statistics.txt")
        t = s["time"]
        ax.plot(t, s["kinetic_energy"], label=label + " kinetic")
        ax.plot(t, s["strain_energy"], "--", label=label + " strain")
        ax.plot(t, s["total_energy"], ":", label=label + " total")
        d = np.hypot(s["body2_x"] - s["body1_x"], s["body2_y"] - s["body1_y"])
        bx.plot(t, d, label=label)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("energy [J/m]")
    ax.legend(fontsize=7)
    ax.set_title("Two disks: energies")
    bx.set_xlabel("time [s]")
    bx.set_ylabel("distance of the centres of mass [m]")
    bx.axhline(0.4, color="grey", lw=0.5)
    bx.legend(fontsize=7)
    bx.set_title("Two disks: centres (touch at 0.4)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
