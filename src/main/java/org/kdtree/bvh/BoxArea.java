package org.kdtree.bvh;

/** The SAH's surface area of a box stored as k minima then k maxima in a flat array (as {@link org.kdtree.geom.Box#surfaceArea()}). */
final class BoxArea {
    private BoxArea() {
    }

    /** {@return the sum of the measures of the 2k faces of the k-D box whose minima start at {@code o} of {@code box}} */
    static double of(double[] box, int o, int k) {
        if (k == 3) {
            double x = box[o + 3] - box[o], y = box[o + 4] - box[o + 1], z = box[o + 5] - box[o + 2];
            return 2 * (x * y + y * z + z * x);
        }
        double sum = 0;
        for (int skip = 0; skip < k; skip++) {
            double face = 1;
            for (int a = 0; a < k; a++) if (a != skip) face *= box[o + k + a] - box[o + a];
            sum += face;
        }
        return 2 * sum;
    }
}
