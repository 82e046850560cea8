package org.kdtree.kdtree;

import org.kdtree.geom.SplitPlane;

/**
 * The recursion's calls into a builder's own code, {@code terminate} and {@code findPlane}: each
 * reported to the build's watch (so a supervisor can tell a hung call), and whatever it throws,
 * or a plane the recursion cannot use, named as that builder's fault ({@link BuilderFault}).
 */
final class BuilderCalls {
    private BuilderCalls() {
    }

    /** {@code b.terminate(context, node)}. */
    static boolean terminate(KdTreeBuilder b, BuildContext context, BuildWatch watch, BuildNode node) {
        watch.enter(BuildWatch.TERMINATE, node.depth(), node.size());
        try {
            return b.terminate(context, node);
        } catch (ThreadDeath stopped) {
            throw stopped; // a supervisor stopped the thread: it has reported why
        } catch (RuntimeException | Error e) {
            throw BuilderFaults.threw(b, BuilderFault.TERMINATE, node, e);
        } finally {
            watch.leave();
        }
    }

    /** {@code b.findPlane(context, node)}, checked: on one of the node's axes, inside its voxel. */
    static SplitPlane findPlane(KdTreeBuilder b, BuildContext context, BuildWatch watch, BuildNode node) {
        watch.enter(BuildWatch.FIND_PLANE, node.depth(), node.size());
        SplitPlane p;
        try {
            p = b.findPlane(context, node);
        } catch (ThreadDeath stopped) {
            throw stopped;
        } catch (RuntimeException | Error e) {
            throw BuilderFaults.threw(b, BuilderFault.FIND_PLANE, node, e);
        } finally {
            watch.leave();
        }
        return checked(b, p, node);
    }

    /** The plane findPlane returned, if the recursion can use it; else the builder's fault. */
    private static SplitPlane checked(KdTreeBuilder b, SplitPlane p, BuildNode node) {
        if (p == null) throw BuilderFaults.badPlane(b, node, "returned null",
                "return a plane for every node that terminate does not make a leaf");
        int k = node.dimension();
        if (p.axis() >= k) throw BuilderFaults.badPlane(b, node, "chose axis " + p.axis() + " in " + k + "-D",
                "the axis must be 0 .. " + (k - 1));
        int at = 2 * k * node.child() + p.axis();
        double[] v = node.store().voxel(node.depth());
        if (p.position() < v[at] || p.position() > v[at + k])
            throw BuilderFaults.badPlane(b, node, "chose x" + p.axis() + " = " + p.position() + ", outside the voxel " + node.voxel(),
                    "findPlane must return a plane on one of the node's axes, inside its voxel");
        return p;
    }
}
