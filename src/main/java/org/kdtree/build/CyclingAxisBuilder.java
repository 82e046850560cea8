package org.kdtree.build;

import org.kdtree.limits.Limits;
import org.kdtree.tree.CostModel;

/**
 * The talk's basic methods (section 3.2): the axis cycles with the depth,
 * {@code n = D(V) mod k}, and the build stops on the simple rule of section 3.2.3,
 * {@code |T| <= Kmintri or D(V) >= Kmaxdepth}. Subclasses choose only the position xi.
 */
public abstract class CyclingAxisBuilder extends KdTreeBuilder {
    private int minPrimitives = Setting.MIN_PRIMITIVES.defaultValue();

    /**
     * The axis for this node: {@code D(V) mod k}.
     *
     * @param node the node to split
     * @return its depth modulo the dimension
     */
    protected static int axis(BuildNode node) {
        return node.depth() % node.dimension();
    }

    @Override protected boolean terminate(BuildContext context, BuildNode node) {
        return node.size() <= minPrimitives || node.depth() >= context.depthCap();
    }

    /** {@return Kmintri}: a node with at most this many primitives becomes a leaf (default: {@link Setting#MIN_PRIMITIVES}). */
    public int minPrimitives() { return minPrimitives; }

    /**
     * Sets Kmintri (>= 0).
     *
     * @param n Kmintri
     * @return this builder
     */
    public CyclingAxisBuilder minPrimitives(int n) {
        this.minPrimitives = Limits.MIN_PRIMITIVES.check("minPrimitives (Kmintri)", n);
        return this;
    }

    // The base class's setters, returning this type, so that a chain may end in minPrimitives.

    @Override public CyclingAxisBuilder maxDepth(int depth) { super.maxDepth(depth); return this; }

    @Override public CyclingAxisBuilder depthFactor(double c) { super.depthFactor(c); return this; }

    @Override public CyclingAxisBuilder referenceBudget(int perPrimitive) { super.referenceBudget(perPrimitive); return this; }

    @Override public CyclingAxisBuilder costModel(CostModel model) { super.costModel(model); return this; }

    @Override public CyclingAxisBuilder perfectSplits(boolean on) { super.perfectSplits(on); return this; }

    @Override public CyclingAxisBuilder threads(int n) { super.threads(n); return this; }

    @Override public String describeSettings() {
        return "Kmintri=" + minPrimitives + " " + super.describeSettings();
    }
}
