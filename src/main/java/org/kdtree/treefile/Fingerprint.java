package org.kdtree.treefile;

import java.util.Locale;
import org.kdtree.geom.Box;
import org.kdtree.shape.PointsKd;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.shape.TriangleMesh;

/**
 * What a saved tree was built over, in four numbers: the kind of primitives, their dimension,
 * their count and a 64-bit hash of their coordinates in order (a mesh's triangles corner by
 * corner, whatever vertices they share; each 2-D shape's kind and coordinates; each point's; for
 * other primitives their bounds). A tree loaded over primitives of another fingerprint would
 * answer for primitives that are not there, so the reader refuses it, naming what differs.
 *
 * @param kind      {@link #TRIANGLES}, {@link #SHAPES}, {@link #POINTS} or {@link #OTHER}
 * @param dimension k
 * @param count     the number of primitives
 * @param hash      the hash of their coordinates
 */
record Fingerprint(int kind, int dimension, int count, long hash) {
    /** The kinds of primitives. */
    static final int OTHER = 0, TRIANGLES = 1, SHAPES = 2, POINTS = 3;

    /** {@return the fingerprint of {@code p}} */
    static Fingerprint of(Primitives p) {
        Hash h = new Hash();
        int kind;
        if (p instanceof TriangleMesh m) {
            kind = TRIANGLES;
            for (int t = 0; t < m.size(); t++)
                for (int c = 0; c < 3; c++)
                    for (int a = 0; a < 3; a++) h.add(m.corner(t, c, a));
        } else if (p instanceof Scene2D s) {
            kind = SHAPES;
            for (Shape2D shape : s.shapes()) {
                h.add(shape.keyword().hashCode());
                for (double c : shape.coords()) h.add(c);
            }
        } else if (p instanceof PointsKd pts) {
            kind = POINTS;
            for (int i = 0; i < pts.size(); i++)
                for (int a = 0; a < pts.dimension(); a++) h.add(pts.coord(i, a));
        } else {
            kind = OTHER;
            Box b = new Box(p.dimension());
            for (int i = 0; i < p.size(); i++) {
                p.bounds(i, b);
                for (int a = 0; a < p.dimension(); a++) h.add(b.min(a)).add(b.max(a));
            }
        }
        return new Fingerprint(kind, p.dimension(), p.size(), h.value());
    }

    /** {@return the primitives in words}, e.g. "5,804 triangles (3-D)" */
    String describe() {
        String what = switch (kind) {
            case TRIANGLES -> "triangles";
            case SHAPES -> "2-D shapes";
            case POINTS -> "points";
            default -> "primitives";
        };
        return String.format(Locale.ROOT, "%,d %s (%d-D)", count, what, dimension);
    }

    /** {@return how {@code scene} differs from these primitives, in words, or null if it does not} */
    String mismatch(Fingerprint scene) {
        if (scene.kind != kind || scene.dimension != dimension || scene.count != count)
            return "the tree was built over " + describe() + ", the scene has " + scene.describe();
        if (scene.hash != hash)
            return String.format(Locale.ROOT, "the tree was built over other %s: the same count, but their coordinates differ"
                    + " (fingerprint %016x, the scene's %016x)", describe(), hash, scene.hash);
        return null;
    }

    /** A 64-bit hash of a sequence of doubles, bit for bit (so -0.0 is not 0.0), mixed as SplitMix64 mixes. */
    private static final class Hash {
        private long h = 0x9E3779B97F4A7C15L;

        Hash add(double x) {
            return add(Double.doubleToLongBits(x));
        }

        Hash add(long bits) {
            h = Long.rotateLeft(h ^ mix(bits), 27) * 0x94D049BB133111EBL + 0x9E3779B97F4A7C15L;
            return this;
        }

        long value() { return mix(h); }

        private static long mix(long z) {
            z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
            z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
            return z ^ (z >>> 31);
        }
    }
}
