package org.kdtree.compare;

import java.util.List;
import java.util.Random;
import org.kdtree.generate.Points;
import org.kdtree.kdtree.SlidingMidpointBuilder;
import org.kdtree.shape.PointsKd;

/**
 * The families of point sets issue 48 names (uniform, Gaussian clusters, a ring, a grid with
 * jitter, a line with noise), each instance drawn from its own seed and then shifted and scaled
 * uniformly at random: the data a similarity search should group by family.
 */
final class Families {
    /** The family names, in the order of {@link #instance}'s {@code family}. */
    static final List<String> NAMES = List.of("uniform", "clusters", "ring", "jittered grid", "noisy line");

    private Families() {
    }

    /** {@return instance {@code seed} of a family: {@code n} k-D points, not yet moved} */
    static PointsKd instance(int family, int n, int k, long seed) {
        return switch (family) {
            case 0 -> Points.uniform(n, k, seed);
            case 1 -> Points.clustered(n, k, seed);
            case 2 -> Points.ring(n, k, 0.02, seed);
            case 3 -> Points.jitteredGrid(n, k, Math.max(2, (int) Math.round(Math.pow(n / 32.0, 1.0 / k))), 0.05, seed);
            case 4 -> Points.line(n, k, 0.02, seed);
            default -> throw new IllegalArgumentException("no family " + family);
        };
    }

    /** {@return the points shifted by up to 1000 per axis and scaled by 0.01 to 100, at random from {@code seed}} */
    static PointsKd moved(PointsKd p, long seed) {
        Random r = new Random(seed);
        int k = p.dimension();
        double scale = Math.pow(10, -2 + 4 * r.nextDouble());
        double[] shift = new double[k];
        for (int a = 0; a < k; a++) shift[a] = 2000 * r.nextDouble() - 1000;
        return moved(p, scale, shift);
    }

    /** {@return the points times {@code scale}, plus {@code shift}} */
    static PointsKd moved(PointsKd p, double scale, double[] shift) {
        int k = p.dimension(), n = p.size();
        double[] c = new double[n * k];
        for (int i = 0; i < n; i++) for (int a = 0; a < k; a++) c[i * k + a] = p.coord(i, a) * scale + shift[a];
        return new PointsKd(k, c);
    }

    /** {@return the signature of the sliding-midpoint tree over the points} */
    static TreeSignature signature(PointsKd p) {
        return TreeSignature.of(new SlidingMidpointBuilder().build(p));
    }
}
