package org.kdtree.render;

import java.util.Arrays;

/**
 * Rays kept as columns, origin and direction per axis, in arrays that grow as they are needed and
 * are then kept: the rays of a block's ray trees ({@link RayTree}) and its shadow rays ({@link
 * Shadows}), until they are gathered into packets.
 */
final class RayColumns {
    double[] ox = new double[0], oy = ox, oz = ox, dx = ox, dy = ox, dz = ox;

    /** Makes room for rays {@code 0 .. n - 1}, keeping those it holds. */
    void grow(int n) {
        ox = Arrays.copyOf(ox, n);
        oy = Arrays.copyOf(oy, n);
        oz = Arrays.copyOf(oz, n);
        dx = Arrays.copyOf(dx, n);
        dy = Arrays.copyOf(dy, n);
        dz = Arrays.copyOf(dz, n);
    }

    /** Sets ray {@code i} to origin {@code o} and direction {@code d}. */
    void set(int i, double[] o, double[] d) {
        ox[i] = o[0];
        oy[i] = o[1];
        oz[i] = o[2];
        dx[i] = d[0];
        dy[i] = d[1];
        dz[i] = d[2];
    }
}
