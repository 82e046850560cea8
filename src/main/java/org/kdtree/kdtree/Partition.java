package org.kdtree.kdtree;

import org.kdtree.geom.Box;
import org.kdtree.geom.Tolerance;
import org.kdtree.shape.Primitives;

/**
 * The partition step of Algorithm 1, per primitive: which children it goes to, and its clipped
 * bounds there. {@link BoundsSplit} and {@link EventSplit} apply it to a whole node.
 */
final class Partition {
    private Partition() {
    }

    /** Where a primitive goes relative to a split plane, from its clipped bounds on the plane's axis. */
    enum Side { LEFT, RIGHT, BOTH }

    /**
     * The side of a primitive with clipped bounds [lo, hi] on the axis of the plane at {@code xi}:
     * one lying in the plane goes where {@code planarLeft} says.
     */
    static Side classify(double lo, double hi, double xi, boolean planarLeft) {
        if (lo == xi && hi == xi) return planarLeft ? Side.LEFT : Side.RIGHT;
        if (hi <= xi) return Side.LEFT;
        if (lo >= xi) return Side.RIGHT;
        return Side.BOTH;
    }

    /**
     * Bounds of a straddling primitive (parent bounds at slot {@code j}) in the children of {@code voxel} cut at
     * {@code x_axis = xi}, written at {@code left[2k atL ..]} and
     * {@code right[2k atR ..]}; returns which children it goes to (bit 0: left, bit 1: right).
     * With perfect splits: the exact clip ({@link Primitives#clipSplit}). The parent's bounds are
     * padded by a few ulps, so a primitive that merely reaches the plane can look like a
     * straddler; its exact clip to the far child is then empty. It is clipped again to the child
     * grown by a hair: if it touches that, it keeps the (tight) sliver at the face; if not, it is
     * not in this child. Without perfect splits: the parent's bounds cut by each child voxel.
     */
    static int straddlerBounds(Primitives prims, int prim, double[] parent, int j, Box voxel, int axis, double xi,
                               boolean perfect, Box tmpL, Box tmpR, double[] left, int atL, double[] right, int atR) {
        int k = voxel.dimension();
        if (!perfect) {
            for (int a = 0; a < k; a++) {
                double lo = parent[2 * k * j + a], hi = parent[2 * k * j + k + a];
                left[2 * k * atL + a] = lo;
                left[2 * k * atL + k + a] = a == axis ? Math.min(hi, xi) : hi;
                right[2 * k * atR + a] = a == axis ? Math.max(lo, xi) : lo;
                right[2 * k * atR + k + a] = hi;
            }
            return 3;
        }
        prims.clipSplit(prim, voxel, axis, xi, tmpL, tmpR);
        int to = 0;
        if (!tmpL.isEmpty() || touches(prims, prim, voxel.lowerPart(axis, xi), tmpL)) { write(tmpL, left, atL); to |= 1; }
        if (!tmpR.isEmpty() || touches(prims, prim, voxel.upperPart(axis, xi), tmpR)) { write(tmpR, right, atR); to |= 2; }
        return to;
    }

    /**
     * Whether a primitive whose exact clip to {@code child} came out empty touches the child grown
     * by a hair; if so, {@code dest} gets the sliver's bounds, kept on the face it touches.
     */
    private static boolean touches(Primitives prims, int prim, Box child, Box dest) {
        int k = child.dimension();
        prims.clip(prim, grown(child), dest);
        if (dest.isEmpty()) return false;
        dest.intersect(child);
        for (int a = 0; a < k; a++) { // keep a valid box on the face the sliver touches
            if (dest.min(a) > dest.max(a)) {
                double face = dest.max(a) < child.min(a) ? child.min(a) : child.max(a);
                dest.setMin(a, face).setMax(a, face);
            }
        }
        return true;
    }

    /** Every primitive's own bounds, the root's clipped bounds: slot i of {@code dest} ({@code 2k} values a slot) for primitive i. */
    static void writeAllBounds(Primitives prims, double[] dest) {
        Box b = new Box(prims.dimension());
        for (int i = 0; i < prims.size(); i++) {
            prims.bounds(i, b);
            write(b, dest, i);
        }
    }

    /** Writes {@code b} as the clipped bounds at slot {@code at} of {@code dest} ({@code 2k} values a slot). */
    static void write(Box b, double[] dest, int at) {
        int k = b.dimension();
        for (int a = 0; a < k; a++) {
            dest[2 * k * at + a] = b.min(a);
            dest[2 * k * at + k + a] = b.max(a);
        }
    }

    /** The box grown on every side by about 8 units in the last place of its coordinates. */
    private static Box grown(Box b) {
        Box g = b.copy();
        for (int a = 0; a < b.dimension(); a++) {
            double pad = Tolerance.BOX_PAD * Math.max(Math.abs(b.min(a)), Math.abs(b.max(a))) + Double.MIN_NORMAL;
            g.setMin(a, b.min(a) - pad).setMax(a, b.max(a) + pad);
        }
        return g;
    }
}
