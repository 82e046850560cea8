package org.kdtree.kdtree;

import java.util.ArrayList;
import java.util.List;
import org.kdtree.accel.Setting;
import org.kdtree.limits.Limits;

/**
 * The talk's basic methods (section 3.2): the axis cycles with the depth,
 * {@code n = D(V) mod k}, and the build stops on the simple rule of section 3.2.3,
 * {@code |T| <= Kmintri or D(V) >= Kmaxdepth}. Subclasses choose only the position xi.
 */
public abstract class CyclingAxisBuilder extends KdTreeBuilder {
    /** Kmintri, the median builders' smallest node worth splitting. */
    public static final Setting<Integer> MIN_PRIMITIVES = Setting.whole("--min-prims", Limits.MIN_PRIMITIVES, 2,
            "a voxel with at most this many primitives becomes a leaf");

    private static final List<Setting<?>> ROWS = rows();

    private static List<Setting<?>> rows() {
        List<Setting<?>> rows = new ArrayList<>(KdTreeBuilder.ROWS);
        rows.add(MIN_PRIMITIVES);
        return List.copyOf(rows);
    }

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
        return node.size() <= minPrimitives() || node.depth() >= context.depthCap();
    }

    /** {@return Kmintri}: a node with at most this many primitives becomes a leaf (default 2). */
    public int minPrimitives() { return settings().get(MIN_PRIMITIVES); }

    /**
     * Sets Kmintri (>= 0).
     *
     * @param n Kmintri
     * @return this builder
     */
    public CyclingAxisBuilder minPrimitives(int n) {
        with(MIN_PRIMITIVES, n);
        return this;
    }

    /** {@return the kd-tree builders' rows and Kmintri} */
    @Override public List<Setting<?>> settingRows() { return ROWS; }


    @Override public String describeSettings() {
        return "Kmintri=" + minPrimitives() + " " + super.describeSettings();
    }
}
