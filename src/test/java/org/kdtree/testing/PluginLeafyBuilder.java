package org.kdtree.testing;

import java.util.ArrayList;
import java.util.List;
import org.kdtree.accel.Setting;
import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.limits.Limit;

/**
 * A plug-in's builder with a setting of its own, as a student declares one: a row with its option,
 * range, default and help, listed in {@link #settingRows()} and read from the builder's settings.
 * Voxel midpoints on the longest axis; a node of at most "leaf limit" primitives is a leaf.
 */
public class PluginLeafyBuilder extends KdTreeBuilder {
    /** The builder's own row: the command line's {@code --leaf-limit}, the workbench's spinner. */
    public static final Setting<Integer> LEAF_LIMIT = Setting.whole("--leaf-limit", Limit.whole("leaf limit", 1, 1000), 8,
            "the largest node the plug-in makes a leaf of");

    private static final List<Setting<?>> ROWS = rows();

    private static List<Setting<?>> rows() {
        List<Setting<?>> rows = new ArrayList<>(new PluginMidpointBuilder().settingRows());
        rows.add(LEAF_LIMIT);
        return List.copyOf(rows);
    }

    @Override public String name() { return "plugin-leafy"; }

    @Override public List<Setting<?>> settingRows() { return ROWS; }

    @Override protected boolean terminate(BuildContext c, BuildNode n) {
        return n.size() <= settings().get(LEAF_LIMIT) || n.depth() >= c.depthCap();
    }

    @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) {
        int axis = 0;
        for (int a = 1; a < n.dimension(); a++) if (n.voxel().extent(a) > n.voxel().extent(axis)) axis = a;
        return new SplitPlane(axis, n.voxel().min(axis) + 0.5 * n.voxel().extent(axis));
    }

    @Override public String describeSettings() {
        return "leafLimit=" + settings().get(LEAF_LIMIT) + " " + super.describeSettings();
    }
}
