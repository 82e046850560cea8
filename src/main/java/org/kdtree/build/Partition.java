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
                    if (childBounds(prims, prim, src, j, lv, perfect, tmp, lc, il)) lr[il++] = prim;
                    if (childBounds(prims, prim, src, j, rv, perfect, tmp, rc, ir)) rr[ir++] = prim;
                }
            }
        }
        return new Children(child(lv, lr, lc, il, node), child(rv, rr, rc, ir, node));
    }

    private static BuildNode child(Box voxel, int[] refs, double[] clipped, int count, BuildNode parent) {
        if (count < refs.length) {
            refs = java.util.Arrays.copyOf(refs, count);
            clipped = java.util.Arrays.copyOf(clipped, 2 * voxel.dimension() * count);
        }
        return new BuildNode(voxel, refs, clipped, parent.depth() + 1);
    }

    /**
     * Bounds of a straddling primitive in a child voxel, written at {@code dest[2k at ..]}.
     * With perfect splits: the exact clip. The parent's bounds are padded by a few ulps, so a
     * primitive that merely reaches the plane can look like a straddler; its exact clip to the far
     * child is then empty. It is clipped again to the child grown by a hair: if it touches that,
     * it keeps the (tight) sliver at the face; if not, it is not in this child and false is returned.
     * Without perfect splits: the parent's bounds cut by the child voxel.
     */
    static boolean childBounds(Primitives prims, int prim, double[] parent, int j, Box child, boolean perfect,
                               Box tmp, double[] dest, int at) {
        int k = child.dimension();
        if (perfect) {
            prims.clip(prim, child, tmp);
            if (tmp.isEmpty()) {
                prims.clip(prim, grown(child), tmp);
                if (tmp.isEmpty()) return false;
                tmp.intersect(child);
                for (int a = 0; a < k; a++) { // keep a valid box on the face the sliver touches
                    if (tmp.min(a) > tmp.max(a)) {
                        double face = tmp.max(a) < child.min(a) ? child.min(a) : child.max(a);
                        tmp.setMin(a, face).setMax(a, face);
                    }
                }
            }
            for (int a = 0; a < k; a++) {
                dest[2 * k * at + a] = tmp.min(a);
                dest[2 * k * at + k + a] = tmp.max(a);
            }
            return true;
        }
        for (int a = 0; a < k; a++) {
            dest[2 * k * at + a] = Math.max(parent[2 * k * j + a], child.min(a));
            dest[2 * k * at + k + a] = Math.min(parent[2 * k * j + k + a], child.max(a));
        }
        return true;
    }

    /** The box grown on every side by about 8 units in the last place of its coordinates. */
    private static Box grown(Box b) {
        Box g = b.copy();
        for (int a = 0; a < b.dimension(); a++) {
            double pad = 2e-15 * Math.max(Math.abs(b.min(a)), Math.abs(b.max(a))) + Double.MIN_NORMAL;
            g.setMin(a, b.min(a) - pad).setMax(a, b.max(a) + pad);
        }
        return g;
    }
}
