package org.kdtree.compare;

/**
 * The distance between two {@link TreeSignature}s, in [0, 1]: the weighted mean of the
 * {@link Term}s, each in [0, 1]. Equal signatures are at 0. Reads the signatures' arrays in place
 * and allocates nothing but the result.
 *
 * @param total the weighted mean of the terms
 * @param terms each {@link Term}'s value, in the order of {@link Term#values()}
 */
public record TreeDistance(double total, double[] terms) {
    private static final Term[] TERMS = Term.values();

    /** {@return each term's value, in the order of {@link Term#values()}} (a copy) */
    @Override public double[] terms() {
        return terms.clone();
    }

    /**
     * {@return the distance between two signatures, with its terms}
     *
     * @param a a signature
     * @param b another, of data of the same dimension
     * @throws IllegalArgumentException if the dimensions differ
     */
    public static TreeDistance between(TreeSignature a, TreeSignature b) {
        double[] terms = new double[TERMS.length];
        double total = 0;
        for (Term t : TERMS) {
            terms[t.ordinal()] = term(t, a, b);
            total += t.weight() * terms[t.ordinal()];
        }
        return new TreeDistance(Math.min(1, total), terms);
    }

    /**
     * {@return the total distance alone} (what a ranking needs: no allocation)
     *
     * @param a a signature
     * @param b another, of data of the same dimension
     * @throws IllegalArgumentException if the dimensions differ
     */
    public static double of(TreeSignature a, TreeSignature b) {
        double total = 0;
        for (Term t : TERMS) total += t.weight() * term(t, a, b);
        return Math.min(1, total);
    }

    /**
     * {@return one term's value, in [0, 1]}
     *
     * @param term which term
     */
    public double term(Term term) {
        return terms[term.ordinal()];
    }

    /**
     * {@return one term of the distance between two signatures, in [0, 1]}
     *
     * @param term which term
     * @param a    a signature
     * @param b    another, of data of the same dimension
     * @throws IllegalArgumentException if the dimensions differ
     */
    public static double term(Term term, TreeSignature a, TreeSignature b) {
        if (a.dimension != b.dimension)
            throw new IllegalArgumentException("cannot compare trees over " + a.dimension + "-D and " + b.dimension + "-D data");
        return switch (term) {
            case VOLUMES -> Histograms.totalVariation(a.volumes, b.volumes, 0, a.volumes.length);
            case DEPTHS -> Histograms.totalVariation(a.depths, b.depths, 0, a.depths.length);
            case SPLITS -> splits(a, b);
            case OCCUPANCY -> Histograms.weightedJaccard(a.occupancy, b.occupancy);
        };
    }

    /**
     * The mean, over the levels where either tree splits, of the total variation of the level's
     * split positions pooled over the axes (1 where only one tree splits). Pooled, because which
     * axis of a near-cubic voxel is the longest, and so split first, is decided by the data's
     * noise (rounding, even): two samples of one cube may split x then y, or y then x, at the
     * same positions.
     */
    private static double splits(TreeSignature a, TreeSignature b) {
        int bins = TreeSignature.POSITION_BINS, block = a.dimension * bins, levels = 0;
        double sum = 0;
        for (int level = 0; level < TreeSignature.SPLIT_DEPTHS; level++) {
            int from = level * block, to = from + block;
            boolean inA = any(a.splits, from, to), inB = any(b.splits, from, to);
            if (!inA && !inB) continue;
            levels++;
            if (!inA || !inB) { sum += 1; continue; }
            double l1 = 0;
            for (int bin = 0; bin < bins; bin++) {
                double pa = 0, pb = 0;
                for (int i = from + bin; i < to; i += bins) { pa += a.splits[i]; pb += b.splits[i]; }
                l1 += Math.abs(pa - pb);
            }
            sum += Math.min(1, l1 / 2);
        }
        return levels > 0 ? sum / levels : 0;
    }

    private static boolean any(double[] h, int from, int to) {
        for (int i = from; i < to; i++) if (h[i] > 0) return true;
        return false;
    }
}
