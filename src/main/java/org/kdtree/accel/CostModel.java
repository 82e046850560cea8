package org.kdtree.accel;

/**
 * The SAH's two constants: Kt, the cost of traversing a node, and Ki, the cost of
 * intersecting a ray with one primitive (talk, section 3.3.1). Wald and Havran use
 * Kt = 15, Ki = 20.
 */
public record CostModel(double kt, double ki) {
    /** Wald and Havran's constants, Kt = 15 and Ki = 20. */
    public static final CostModel WALD_HAVRAN = new CostModel(15, 20);

    /**
     * Checks the constants.
     *
     * @param kt Kt, the cost of traversing a node
     * @param ki Ki, the cost of intersecting a ray with one primitive
     * @throws IllegalArgumentException unless Kt &ge; 0 and Ki &gt; 0, both finite
     */
    public CostModel {
        if (!(kt >= 0) || !(ki > 0) || !Double.isFinite(kt) || !Double.isFinite(ki))
            throw new IllegalArgumentException("need Kt >= 0 and Ki > 0, got Kt=" + kt + " Ki=" + ki);
    }
}
