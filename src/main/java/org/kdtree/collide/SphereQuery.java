package org.kdtree.collide;

import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.Mailbox;

/**
 * What both sphere queries keep of their scene: the tree, its primitives' exact tests, the root
 * voxel's corners, the scene's scale (for the voxel padding) and a mailbox. Per query object, so
 * per thread.
 */
abstract class SphereQuery {
    final KdTree tree;
    final Collider prims;
    final int k;
    final double[] lo, hi;
    final double sceneScale;
    final Mailbox tested;

    SphereQuery(KdTree tree, Collider prims) {
        tree.requireDimension(prims.dimension(), "primitives");
        this.tree = tree;
        this.prims = prims;
        k = tree.dimension();
        Box b = tree.bounds();
        lo = b.minCorner();
        hi = b.maxCorner();
        sceneScale = b.magnitude();
        tested = new Mailbox(prims.size());
    }
}
