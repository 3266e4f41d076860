#!/usr/bin/python3
"""Write prm/meshes/sliver_bar.msh: the 25 m x 2 m bar as an unstructured
Gmsh (format 2.2) triangle mesh with a strip of sliver triangles (aspect
ratio about 40) across its middle and perturbed interior vertices elsewhere.
Boundaries: physical lines left (1), right (2), bottom (3), top (4)."""
import os
import random

random.seed(7)
xs = [0, 2, 4.5, 6.5, 8.7, 10.5, 12.48, 12.5, 12.52, 14.5, 16.3, 18.5, 20.4, 22.8, 25]
ys = [0, 0.7, 1.3, 2]
nodes, index = [], {}
for j, y in enumerate(ys):
    for i, x in enumerate(xs):
        px, py = x, y
        interior = 0 < i < len(xs) - 1 and 0 < j < len(ys) - 1 and x not in (12.48, 12.5, 12.52)
        if interior:
            px += random.uniform(-0.3, 0.3)
            py += random.uniform(-0.1, 0.1)
        index[(i, j)] = len(nodes) + 1
        nodes.append((px, py))
tris, lines = [], []
for j in range(len(ys) - 1):
    for i in range(len(xs) - 1):
        a, b = index[(i, j)], index[(i + 1, j)]
        c, d = index[(i + 1, j + 1)], index[(i, j + 1)]
        if (i + j) % 2 == 0:
            tris += [(a, b, c), (a, c, d)]
        else:
            tris += [(a, b, d), (b, c, d)]
for j in range(len(ys) - 1):
    lines.append((1, index[(0, j)], index[(0, j + 1)]))
    lines.append((2, index[(len(xs) - 1, j)], index[(len(xs) - 1, j + 1)]))
for i in range(len(xs) - 1):
    lines.append((3, index[(i, 0)], index[(i + 1, 0)]))
    lines.append((4, index[(i, len(ys) - 1)], index[(i + 1, len(ys) - 1)]))
out = os.path.join(os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")),
                   "prm", "meshes", "sliver_bar.msh")
with open(out, "w") as f:
    f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n4\n"
            '1 1 "left"\n1 2 "right"\n1 3 "bottom"\n1 4 "top"\n$EndPhysicalNames\n')
    f.write(f"$Nodes\n{len(nodes)}\n")
    for k, (x, y) in enumerate(nodes, 1):
        f.write(f"{k} {x:.12g} {y:.12g} 0\n")
    f.write(f"$EndNodes\n$Elements\n{len(lines) + len(tris)}\n")
    k = 1
    for tag, a, b in lines:
        f.write(f"{k} 1 2 {tag} {tag} {a} {b}\n"); k += 1
    for a, b, c in tris:
        f.write(f"{k} 2 2 10 10 {a} {b} {c}\n"); k += 1
    f.write("$EndElements\n")
print(out)
