package org.kdtree.compare;

/** The histogram arithmetic of signatures and their distance: tent binning, total variation, weighted Jaccard. */
final class Histograms {
    private Histograms() {
    }

    /**
     * Adds {@code weight} at the fractional bin {@code x} (0 to {@code bins - 1}) of the
     * histogram at {@code offset}, shared linearly between the two nearest bins.
     */
    static void addTent(double[] h, int offset, int bins, double x, double weight) {
        double clamped = Math.max(0, Math.min(bins - 1, x));
        int lo = (int) Math.floor(clamped);
        double up = clamped - lo;
        h[offset + lo] += weight * (1 - up);
        if (up > 0) h[offset + lo + 1] += weight * up;
    }

    /** {@return half the L1 distance of two distributions over {@code [from, to)}} (in [0, 1] when each sums to 1) */
    static double totalVariation(double[] p, double[] q, int from, int to) {
        double sum = 0;
        for (int i = from; i < to; i++) sum += Math.abs(p[i] - q[i]);
        return Math.min(1, sum / 2);
    }

    /** {@return 1 - sum min / sum max of two non-negative arrays (0 when both are zero)} */
    static double weightedJaccard(double[] p, double[] q) {
        double min = 0, max = 0;
        for (int i = 0; i < p.length; i++) {
            double a = p[i], b = q[i];
            if (a < b) { min += a; max += b; } else { min += b; max += a; }
        }
        return max > 0 ? 1 - min / max : 0;
    }
}
