package org.kdtree.build;

import org.kdtree.geom.Box;
import org.kdtree.geom.SplitPlane;
import org.kdtree.shape.Primitives;

/** The default partition step of Algorithm 1: send each primitive to the children it overlaps. */
final class Partition {
    private Partition() {
    }

    /** Where a primitive goes relative to a split plane, from its clipped bounds on the plane's axis. */
    enum Side { LEFT, RIGHT, BOTH }

    /** The side of a primitive with clipped bounds [lo, hi] on the plane's axis. */
    static Side classify(double lo, double hi, SplitPlane p) {
        double xi = p.position();
        if (lo == xi && hi == xi) return p.planarLeft() ? Side.LEFT : Side.RIGHT;
        if (hi <= xi) return Side.LEFT;
        if (lo >= xi) return Side.RIGHT;
        return Side.BOTH;
    }

    static Children split(Primitives prims, BuildNode node, SplitPlane p) {
        return split(prims, node, p, true);
    }

    static Children split(Primitives prims, BuildNode node, SplitPlane p, boolean perfect) {
        int k = node.dimension(), n = node.size(), axis = p.axis();
        Side[] side = new Side[n];
        int nl = 0, nr = 0;
        for (int j = 0; j < n; j++) {
            side[j] = classify(node.clippedMin(j, axis), node.clippedMax(j, axis), p);
            if (side[j] != Side.RIGHT) nl++;
            if (side[j] != Side.LEFT) nr++;
        }
        Box lv = node.voxel().lowerPart(axis, p.position());
        Box rv = node.voxel().upperPart(axis, p.position());
        int[] lr = new int[nl], rr = new int[nr];
        double[] lc = new double[2 * k * nl], rc = new double[2 * k * nr];
        double[] src = node.clippedBounds();
        Box tmp = new Box(k);
        int il = 0, ir = 0;
        for (int j = 0; j < n; j++) {
            int prim = node.ref(j);
            switch (side[j]) {
                case LEFT -> { lr[il] = prim; System.arraycopy(src, 2 * k * j, lc, 2 * k * il++, 2 * k); }
                case RIGHT -> { rr[ir] = prim; System.arraycopy(src, 2 * k * j, rc, 2 * k * ir++, 2 * k); }
                case BOTH -> {
                    lr[il] = prim;
                    childBounds(prims, prim, src, j, lv, perfect, tmp, lc, il++);
                    rr[ir] = prim;
                    childBounds(prims, prim, src, j, rv, perfect, tmp, rc, ir++);
                }
            }
        }
        return new Children(new BuildNode(lv, lr, lc, node.depth() + 1),
                new BuildNode(rv, rr, rc, node.depth() + 1));
    }

    /**
     * Bounds of a straddling primitive in a child voxel: exact clipping when {@code perfect};
     * otherwise, or if rounding made the exact clip miss a sliver, the parent's clipped bounds
     * cut by the child voxel (always a superset of the true part).
     */
    static void childBounds(Primitives prims, int prim, double[] parent, int j, Box child, boolean perfect,
                            Box tmp, double[] dest, int at) {
        int k = child.dimension();
        boolean clippedOk = false;
        if (perfect) {
            prims.clip(prim, child, tmp);
            clippedOk = !tmp.isEmpty();
        }
        for (int a = 0; a < k; a++) {
            double lo, hi;
            if (clippedOk) {
                lo = tmp.min(a);
                hi = tmp.max(a);
            } else {
                lo = Math.max(parent[2 * k * j + a], child.min(a));
                hi = Math.min(parent[2 * k * j + k + a], child.max(a));
            }
            dest[2 * k * at + a] = lo;
            dest[2 * k * at + k + a] = hi;
        }
    }
}
