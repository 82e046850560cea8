package org.kdtree.testing;

import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/** A broken student's builder for plug-in tests: findPlane reads past the end of an array. */
public class ThrowingBuilder extends KdTreeBuilder {
    @Override public String name() { return "throws"; }
    @Override protected boolean terminate(BuildContext c, BuildNode n) { return n.size() <= 2; }
    @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) {
        double[] middles = new double[n.dimension()];
        return new SplitPlane(0, middles[n.dimension()]); // one past the last axis
    }
}
