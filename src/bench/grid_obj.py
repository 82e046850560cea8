#!/usr/bin/env python3
"""Writes MESH repeated in a G x G grid on the x-z plane (the benchmark spec's grid scene, docs/benchmark-spec.md) as OBJ.
Usage: grid_obj.py MESH.obj G > out.obj   (vertices and triangles only; polygons fan-triangulated)"""
import sys

def read(path):
    """The vertices and triangles of an OBJ file (polygons fan-triangulated, negative indices resolved)."""
    vs, fs = [], []
    with open(path) as f:
        for line in f:
            p = line.split()
            if not p:
                continue
            if p[0] == 'v':
                vs.append(tuple(float(x) for x in p[1:4]))
            elif p[0] == 'f':
                idx = []
                for t in p[1:]:
                    i = int(t.split('/')[0])
                    idx.append(i - 1 if i > 0 else len(vs) + i)
                for j in range(1, len(idx) - 1):
                    fs.append((idx[0], idx[j], idx[j + 1]))
    return vs, fs

def main():
    if len(sys.argv) != 3 or not sys.argv[2].isdigit() or int(sys.argv[2]) < 1:
        sys.exit('usage: grid_obj.py MESH.obj G > out.obj   (G: a whole number, 1 or more)')
    path, g = sys.argv[1], int(sys.argv[2])
    vs, fs = read(path)
    lo = [min(v[a] for v in vs) for a in range(3)]
    hi = [max(v[a] for v in vs) for a in range(3)]
    ex, ez = hi[0] - lo[0], hi[2] - lo[2]
    out = sys.stdout
    n = len(vs)
    for gx in range(g):
        for gz in range(g):
            dx, dz = 1.1 * gx * ex, 1.1 * gz * ez
            for v in vs:
                out.write(f"v {v[0] + dx!r} {v[1]!r} {v[2] + dz!r}\n")
    for c in range(g * g):
        for t in fs:
            out.write(f"f {t[0] + 1 + c * n} {t[1] + 1 + c * n} {t[2] + 1 + c * n}\n")

if __name__ == '__main__':
    main()
