package org.kdtree.testing;

import java.util.ArrayList;
import java.util.List;
import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/** A broken student's builder for grade-class: findPlane allocates without bound and keeps it all. */
public class HoardingBuilder extends KdTreeBuilder {
    private static final List<long[]> KEPT = new ArrayList<>();

    @Override public String name() { return "hoards"; }
    @Override protected boolean terminate(BuildContext c, BuildNode n) { return n.size() <= 2; }
    @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) {
        while (true) KEPT.add(new long[1 << 20]);
    }
}
