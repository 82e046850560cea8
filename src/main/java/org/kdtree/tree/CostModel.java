package org.kdtree.tree;

/**
 * The SAH's two constants: Kt, the cost of traversing a node, and Ki, the cost of
 * intersecting a ray with one primitive (talk, section 3.3.1). Wald and Havran use
 * Kt = 15, Ki = 20.
 */
public record CostModel(double kt, double ki) {
    public static final CostModel WALD_HAVRAN = new CostModel(15, 20);

    public CostModel {
        if (!(kt >= 0) || !(ki > 0) || !Double.isFinite(kt) || !Double.isFinite(ki))
            throw new IllegalArgumentException("need Kt >= 0 and Ki > 0, got Kt=" + kt + " Ki=" + ki);
    }
}
