package org.kdtree.testing;

import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/** A correct but slow student's builder for plug-in tests: 200 ms per decision to stop, then voxel midpoints. */
public class SleepyBuilder extends KdTreeBuilder {
    /** How long each terminate takes. */
    public static final long MILLIS_PER_NODE = 200;

    @Override public String name() { return "sleepy"; }
    @Override protected boolean terminate(BuildContext c, BuildNode n) {
        try {
            Thread.sleep(MILLIS_PER_NODE);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return n.size() <= 2 || n.depth() >= c.depthCap();
    }
    @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) {
        int axis = n.depth() % n.dimension();
        return new SplitPlane(axis, n.voxel().min(axis) + 0.5 * n.voxel().extent(axis));
    }
}
