#!/usr/bin/python3
"""Write the strip footing's mesh (prm/strip_footing.prm) as a Gmsh file.

    /usr/bin/python3 contrib/geomechanics/make_strip_footing_mesh.py
        [--blocks-per-m 8] [--output prm/meshes/strip_footing.msh]

Criss-cross blocks of size h = 1 / blocks-per-m (each square split into 4
triangles around its centre) over the soil, [0, 5] x [0, 2.5] (B = 1 m:
the half footing is 0 <= x <= 0.5 at y = 2.5), and a layer of empty
blocks above the soil surface beside the footing, [0.5, 5] x [2.5, 2.5 +
a], a = max(0.25, 2 h), into which the soil heaves: on a rectangular mesh
whose top is the soil surface the heave beside the footing carries
particles out of the mesh (at 5.5 % of B of settlement with h = 1/16).
Physical lines (boundary names): left (x = 0, the centre line), right
(x = 5), bottom (y = 0), top (the empty layer's top) and footing: the
footing's base (y = 2.5, 0 <= x <= 0.5) and its vertical side (x = 0.5
above the surface), one rigid block. The side belongs to the footing
because with Powell-Sabin the vertex at the re-entrant corner (0.5, 2.5)
is constrained with ties to its neighbours when only the base is
prescribed, and the reactions skip tied DoFs: the base alone then
reported 20 % less than the floor carried (q/c 4.0 against 5.1 from
reaction_bottom_y, h = 1/8). With the side in the footing the corner's
coefficients are all set to the footing's velocity, and footing and
floor agree within 2 %.
"""
import argparse
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))
LENGTH, DEPTH, HALF_WIDTH = 5.0, 2.5, 0.5
NAMES = ['left', 'right', 'bottom', 'footing', 'top']


def write_mesh(path, blocks_per_m):
    n = int(blocks_per_m)
    h = 1.0 / n
    nx, nd = int(round(LENGTH * n)), int(round(DEPTH * n))
    nf = int(round(HALF_WIDTH * n))
    ngap = max(2, int(round(0.25 * n)))
    ny = nd + ngap
    top = (nd + ngap) * h

    def exists(i, j):
        return 0 <= i < nx and 0 <= j < ny and (j < nd or i >= nf)

    nodes, index = [], {}

    def node(key, x, y):
        if key not in index:
            index[key] = len(nodes) + 1
            nodes.append((x, y))
        return index[key]

    tris = []
    for j in range(ny):
        for i in range(nx):
            if not exists(i, j):
                continue
            a = node(('v', i, j), i * h, j * h)
            b = node(('v', i + 1, j), (i + 1) * h, j * h)
            c = node(('v', i + 1, j + 1), (i + 1) * h, (j + 1) * h)
            d = node(('v', i, j + 1), i * h, (j + 1) * h)
            m = node(('c', i, j), (i + 0.5) * h, (j + 0.5) * h)
            # Counter-clockwise, around the block's centre.
            tris += [(a, b, m), (b, c, m), (c, d, m), (d, a, m)]

    lines = []
    for j in range(ny):
        for i in range(nx):
            if not exists(i, j):
                continue
            a, b = index[('v', i, j)], index[('v', i + 1, j)]
            c, d = index[('v', i + 1, j + 1)], index[('v', i, j + 1)]
            if not exists(i, j - 1):
                lines.append((NAMES.index('bottom') + 1, a, b))
            if not exists(i + 1, j):
                lines.append((NAMES.index('right') + 1, b, c))
            if not exists(i, j + 1):
                name = 'footing' if j == nd - 1 and i < nf else 'top'
                lines.append((NAMES.index(name) + 1, c, d))
            if not exists(i - 1, j):
                name = 'left' if i == 0 else 'footing'
                lines.append((NAMES.index(name) + 1, d, a))
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, 'w') as f:
        f.write('$MeshFormat\n2.2 0 8\n$EndMeshFormat\n')
        f.write('$PhysicalNames\n%d\n' % len(NAMES))
        for k, name in enumerate(NAMES, 1):
            f.write('1 %d "%s"\n' % (k, name))
        f.write('$EndPhysicalNames\n$Nodes\n%d\n' % len(nodes))
        for k, (x, y) in enumerate(nodes, 1):
            f.write('%d %.12g %.12g 0\n' % (k, x, y))
        f.write('$EndNodes\n$Elements\n%d\n' % (len(lines) + len(tris)))
        k = 1
        for tag, a, b in lines:
            f.write('%d 1 2 %d %d %d %d\n' % (k, tag, tag, a, b))
            k += 1
        for a, b, c in tris:
            f.write('%d 2 2 10 10 %d %d %d\n' % (k, a, b, c))
            k += 1
        f.write('$EndElements\n')
    return {'h': h, 'cells': len(tris), 'footing_blocks': nf,
            'top': top}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--blocks-per-m', type=int, default=8)
    ap.add_argument('--output', default=os.path.join(
        ROOT, 'prm', 'meshes', 'strip_footing.msh'))
    args = ap.parse_args()
    info = write_mesh(args.output, args.blocks_per_m)
    print('%s: h = %g m, %d triangles, %d blocks under the half footing'
          % (args.output, info['h'], info['cells'], info['footing_blocks']))


if __name__ == '__main__':
    main()
