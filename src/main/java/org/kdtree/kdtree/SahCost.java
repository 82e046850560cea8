package org.kdtree.kdtree;

import org.kdtree.accel.CostModel;
import org.kdtree.geom.Box;

/**
 * The SAH cost of splitting one voxel (talk, section 3.3.2, with the empty-voxel weight of 3.3.4):
 * <pre>
 *   C_V(p) = lambda(p) * ( Kt + Ki * ( SA(V_L)/SA(V) |T_L| + SA(V_R)/SA(V) |T_R| ) )
 *   lambda(p) = lambda if |T_L| = 0 or |T_R| = 0, else 1
 * </pre>
 * One instance serves one voxel. Every plane-search algorithm evaluates costs through this
 * class, so that they all compute the same numbers to the last bit and build the same tree.
 *
 * <p>Child areas are computed without building boxes: cutting axis n at width w leaves a box of
 * area {@code 2 (face_n + w * side_n)}, where {@code face_n} is the product of the other extents
 * and {@code side_n} the sum of the products of all extents but n and one other.
 */
final class SahCost {
    private final CostModel model;
    private final double lambda;
    private final int k;
    private double halfArea, inverseHalfArea;
    /** min, max, face and side per axis, packed in one array: {@code v[4 axis + 0..3]}. */
    private final double[] v;

    /**
     * The SAH cost of splitting {@code voxel}.
     * @param model Kt and Ki
     * @param lambda lambda, the weight of a plane that leaves one child empty
     * @param voxel the voxel V being split
     */
    public SahCost(CostModel model, double lambda, Box voxel) {
        this(model, lambda, voxel.dimension());
        for (int a = 0; a < k; a++) {
            v[4 * a] = voxel.min(a);
            v[4 * a + 1] = voxel.max(a);
        }
        faceAndSide();
    }

    /** A cost to be pointed at one voxel after another with {@link #set} (each node store keeps one for the SAH). */
    SahCost(CostModel model, double lambda, int k) {
        this.model = model;
        this.lambda = lambda;
        this.k = k;
        this.v = new double[4 * k];
    }

    /** Points this cost at the voxel whose minima are {@code box[at .. at + k)} and maxima the next k values. */
    SahCost set(double[] box, int at) {
        for (int a = 0; a < k; a++) {
            v[4 * a] = box[at + a];
            v[4 * a + 1] = box[at + k + a];
        }
        faceAndSide();
        return this;
    }

    private void faceAndSide() {
        if (k == 3) faceAndSide3D();
        else for (int n = 0; n < k; n++) {
            double f = 1, s = 0;
            for (int a = 0; a < k; a++) {
                if (a == n) continue;
                f *= extent(a);
                double prod = 1;
                for (int b = 0; b < k; b++) if (b != n && b != a) prod *= extent(b);
                s += prod;
            }
            v[4 * n + 2] = f;
            v[4 * n + 3] = s;
        }
        halfArea = v[2] + extent(0) * v[3];
        inverseHalfArea = 1 / halfArea;
    }

    /** The loop above written out for k = 3 (every node of a 3-D build makes one): the same products and sums. */
    private void faceAndSide3D() {
        double e0 = extent(0), e1 = extent(1), e2 = extent(2);
        v[2] = e1 * e2;
        v[3] = e2 + e1;
        v[6] = e0 * e2;
        v[7] = e2 + e0;
        v[10] = e0 * e1;
        v[11] = e1 + e0;
    }

    private double extent(int a) {
        return v[4 * a + 1] - v[4 * a];
    }

    /** {@return half the voxel's surface area}; zero for a voxel no ray can meet with positive probability. */
    public double halfArea() { return halfArea; }

    /** {@return Kt, Ki of this cost} */
    public CostModel model() { return model; }

    /**
     * Whether a plane at {@code x} on {@code axis} is a candidate: strictly inside the voxel.
     *
     * @param axis the plane's axis
     * @param x its position
     * @return true if strictly inside
     */
    public boolean inside(int axis, double x) {
        return x > v[4 * axis] && x < v[4 * axis + 1];
    }

    /**
     * C_V(p) for the plane {@code x_axis = x} with {@code nl} and {@code nr} primitives on each side.
     *
     * @param axis the plane's axis
     * @param x its position
     * @param nl primitives on the left
     * @param nr primitives on the right
     * @return the expected cost of the split
     */
    public double cost(int axis, double x, int nl, int nr) {
        int o = 4 * axis;
        double face = v[o + 2], side = v[o + 3];
        double pl = (face + (x - v[o]) * side) * inverseHalfArea;
        double pr = (face + (v[o + 1] - x) * side) * inverseHalfArea;
        double c = model.kt() + model.ki() * (pl * nl + pr * nr);
        return (nl == 0 || nr == 0) ? c * lambda : c;
    }

    /**
     * The cost of making the voxel a leaf: |T| Ki.
     *
     * @param n |T|, the number of primitives
     * @return n Ki
     */
    public double leafCost(int n) {
        return n * model.ki();
    }
}
