#!/usr/bin/python3
"""Write prm/geometry/ring.msh, a body geometry for Bodies/Body k/Shape =
gmsh (Gmsh format 2.2, ASCII): a ring (annulus) centred at (0.5, 0.55) with
radii 0.1 and 0.2, triangulated by a polar grid, in two physical surfaces,
"outer" (radii 0.15 to 0.2, tag 1) and "inner" (0.1 to 0.15, tag 2), so that
a scene can take either or both. The hole has no cells: a body made of the
file is a ring. Written by a script because the Debian machine has no gmsh
binary; a .geo file meshed by gmsh works the same way."""
import math
import os

cx, cy = 0.5, 0.55
radii = [0.1, 0.125, 0.15, 0.175, 0.2]
n_angle = 48
nodes = []
index = {}
for j, r in enumerate(radii):
    for i in range(n_angle):
        phi = 2 * math.pi * i / n_angle
        index[(i, j)] = len(nodes) + 1
        nodes.append((cx + r * math.cos(phi), cy + r * math.sin(phi)))
elements = []
for j in range(len(radii) - 1):
    tag = 2 if radii[j] < 0.15 else 1
    for i in range(n_angle):
        a, b = index[(i, j)], index[((i + 1) % n_angle, j)]
        c, d = index[((i + 1) % n_angle, j + 1)], index[(i, j + 1)]
        # Counter-clockwise: inner edge a -> b, then outwards.
        elements.append((tag, a, b, c))
        elements.append((tag, a, c, d))
path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "prm",
                    "geometry", "ring.msh")
with open(path, "w") as f:
    f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
    f.write('$PhysicalNames\n2\n2 1 "outer"\n2 2 "inner"\n$EndPhysicalNames\n')
    f.write("$Nodes\n%d\n" % len(nodes))
    for k, (x, y) in enumerate(nodes):
        f.write("%d %.15g %.15g 0\n" % (k + 1, x, y))
    f.write("$EndNodes\n$Elements\n%d\n" % len(elements))
    for k, (tag, a, b, c) in enumerate(elements):
        f.write("%d 2 2 %d %d %d %d %d\n" % (k + 1, tag, tag, a, b, c))
    f.write("$EndElements\n")
print("wrote", os.path.normpath(path))
