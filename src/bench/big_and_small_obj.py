#!/usr/bin/env python3
"""Writes MESH (small triangles) inside a room of big ones, crossed by big slanted triangles that
straddle most split planes, as OBJ: the preset study's "scene of big and small triangles"
(docs/sah.md, "Quality presets"). Deterministic (seeded).
Usage: big_and_small_obj.py MESH.obj [BLADES] > out.obj   (default 24 big slanted triangles)"""
import os
import random
import sys

from grid_obj import read

def main():
    if len(sys.argv) not in (2, 3) or not os.path.isfile(sys.argv[1]):
        sys.exit('usage: big_and_small_obj.py MESH.obj [BLADES] > out.obj')
    vs, fs = read(sys.argv[1])
    blades = int(sys.argv[2]) if len(sys.argv) > 2 else 24
    lo = [min(v[a] for v in vs) for a in range(3)]
    hi = [max(v[a] for v in vs) for a in range(3)]
    mid = [(lo[a] + hi[a]) / 2 for a in range(3)]
    half = max(hi[a] - lo[a] for a in range(3)) * 1.5
    big = []
    # the room: a box three times the mesh's size, two triangles a face
    c = [[mid[a] + s * half for a, s in enumerate(signs)] for signs in
         [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1), (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]]
    for q in [(0, 1, 2, 3), (4, 7, 6, 5), (0, 4, 5, 1), (3, 2, 6, 7), (0, 3, 7, 4), (1, 5, 6, 2)]:
        big += [(c[q[0]], c[q[1]], c[q[2]]), (c[q[0]], c[q[2]], c[q[3]])]
    # big slanted triangles through the mesh's box
    rnd = random.Random(47)
    for _ in range(blades):
        big.append(tuple(tuple(mid[a] + rnd.uniform(-1, 1) * (hi[a] - lo[a]) for a in range(3)) for _ in range(3)))
    out = sys.stdout
    for v in vs:
        out.write('v %.7g %.7g %.7g\n' % v)
    for t in big:
        for v in t:
            out.write('v %.7g %.7g %.7g\n' % tuple(v))
    for f in fs:
        out.write('f %d %d %d\n' % (f[0] + 1, f[1] + 1, f[2] + 1))
    n = len(vs)
    for i in range(len(big)):
        out.write('f %d %d %d\n' % (n + 3 * i + 1, n + 3 * i + 2, n + 3 * i + 3))

if __name__ == '__main__':
    main()
