package builder;

import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/** CI's hanging builder: findPlane never returns, and ignores interruption. The contract must say so once, within a minute. */
public class MyBuilder extends KdTreeBuilder {
    private static volatile double spin = 1;

    @Override public String name() {
        return "my-builder";
    }

    @Override protected boolean terminate(BuildContext context, BuildNode node) {
        return node.size() <= 2;
    }

    @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
        while (true) spin += Math.sqrt(spin);
    }
}
