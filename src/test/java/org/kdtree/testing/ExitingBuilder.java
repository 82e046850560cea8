package org.kdtree.testing;

import org.kdtree.build.BuildContext;
import org.kdtree.build.BuildNode;
import org.kdtree.build.KdTreeBuilder;
import org.kdtree.geom.SplitPlane;

/** A broken student's builder for grade-class: findPlane ends the whole JVM. */
public class ExitingBuilder extends KdTreeBuilder {
    @Override public String name() { return "exits"; }
    @Override protected boolean terminate(BuildContext c, BuildNode n) { return n.size() <= 2; }
    @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) {
        System.exit(42);
        return null;
    }
}
