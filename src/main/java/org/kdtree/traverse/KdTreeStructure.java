package org.kdtree.traverse;

import org.kdtree.geom.Box;
import org.kdtree.geom.Ray;
import org.kdtree.tree.KdTree;
import org.kdtree.tree.TreeStats;

/**
 * A kd-tree seen as an {@link AccelerationStructure}: its queries are {@link Traverser}s. Made by
 * {@link AccelerationStructure#of(KdTree)}; public so that a caller holding a structure can reach
 * what only a kd-tree has (the leaves its reference budget made early, say).
 *
 * @param tree the kd-tree
 */
public record KdTreeStructure(KdTree tree) implements AccelerationStructure {
    @Override public String kind() { return "kd-tree"; }
    @Override public int dimension() { return tree.dimension(); }
    @Override public Box bounds() { return tree.bounds(); }
    @Override public TreeStats stats() { return tree.stats(); }
    @Override public RayQuery query(Intersector prims) { return new Traverser(tree, prims); }

    @Override public RayQuery query(Intersector prims, TraversalListener listener) {
        Traverser t = new Traverser(tree, prims);
        return new RayQuery() {
            @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) {
                return t.closestHit(ray, tMin, tMax, hit, listener);
            }

            @Override public boolean anyHit(Ray ray, double tMin, double tMax) {
                return t.anyHit(ray, tMin, tMax, listener);
            }
        };
    }
}
