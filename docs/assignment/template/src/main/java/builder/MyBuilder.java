package builder;

import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/**
 * Your kd-tree builder: decide when a node becomes a leaf (terminate) and where to cut it
 * (findPlane). The base class does the rest (Algorithm 1: the recursion, the partition, the
 * depth cap). Run the contract with {@code mvn test}.
 */
public class MyBuilder extends KdTreeBuilder {
    /** The name the command line, the workbench and the grader know your builder by. */
    @Override public String name() {
        return "my-builder";
    }

    /** terminate(T, V): should this node become a leaf? */
    @Override protected boolean terminate(BuildContext context, BuildNode node) {
        throw new UnsupportedOperationException("TODO: terminate(): when should a node become a leaf?");
    }

    /** findPlane(T, V): the split plane (an axis and a position within node.voxel(); on its face is allowed but useless) for a node that does not terminate. */
    @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
        throw new UnsupportedOperationException("TODO: findPlane(): where should this node be cut?");
    }
}
