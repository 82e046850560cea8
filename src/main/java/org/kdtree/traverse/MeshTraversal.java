package org.kdtree.traverse;

import org.kdtree.geom.Ray;
import org.kdtree.tree.KdTree;
import org.kdtree.tree.Nodes;

/**
 * The silent loop of {@link Traverser}: closest and any hit on a triangle mesh when nobody
 * listens, the hot path of rendering and of {@code raycast}. The same Algorithm 2 and the same
 * robustness rules as the listening loop, from the same pieces: the ray is checked and clipped by
 * the traverser's {@link SceneBox}, nodes are read with {@link Nodes}, triangles are tested by
 * {@link TriangleIntersector#test}, called directly (the JIT inlines it) with the shear computed
 * once per ray. What it leaves out is every call the listening loop makes per step.
 *
 * <p>Why two loops and not one: the JIT compiles a loop once, from the profile of every query that
 * ran it. One loop for both would carry the listener's calls (interior, push, pop, leaf, each
 * primitive) into the compiled hot loop as soon as one JVM both watches and traces (the trade-off
 * study counts steps with {@link TraversalStats} between timed runs of the same traverser; the
 * workbench steps through a traversal and renders). Those calls are megamorphic
 * ({@link TraversalStats}, the workbench's recorder, its pair of them), so none is inlined, and a
 * loop with a call in it, even on a branch this query never takes, reads its fields again after
 * each call instead of once before the loop. Here every call is inlined. Closest and any hit share
 * this loop: they differ in one test per hit.
 *
 * <p>Not thread safe: owned by one traverser, whose mailbox, stack and scene box it shares.
 */
final class MeshTraversal {
    /** A 3-D tree's {@link KdTree#axisBits()}, a constant the JIT folds into the node decoding. */
    private static final int BITS = Nodes.axisBits(3);
    private static final double SLACK = Traverser.SLACK;

    private final int[] nodes;
    private final int[] refs;
    private final double[] corners;
    private final SceneBox scene;
    private final Mailbox mailbox;
    private final int[] stackNode;
    private final double[] stackMin, stackMax;
    private final double[] org = new double[3], inv = new double[3];
    private final Hit scratch = new Hit();

    MeshTraversal(KdTree tree, TriangleIntersector tris, SceneBox scene, Mailbox mailbox, int stackSize) {
        if (tree.axisBits() != BITS) throw new IllegalArgumentException("a 3-D tree's axis field is " + BITS + " bits");
        nodes = tree.nodeArray();
        refs = tree.refArray();
        corners = tris.cornerArray();
        this.scene = scene;
        this.mailbox = mailbox;
        stackNode = new int[stackSize];
        stackMin = new double[stackSize];
        stackMax = new double[stackSize];
    }

    boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) {
        hit.reset();
        return trace(ray, tMin, tMax, hit, false);
    }

    boolean anyHit(Ray ray, double tMin, double tMax) {
        return trace(ray, tMin, tMax, scratch.reset(), true);
    }

    private boolean trace(Ray ray, double tMin, double tMax, Hit hit, boolean any) {
        if (!scene.clip(ray, tMin, tMax)) return false;
        // The watertight test's shear, once per ray.
        int f = TriangleIntersector.frame(ray), kx = f & 3, ky = f >>> 2 & 3, kz = f >>> 4;
        double sz = ray.inverseDirection(kz), sx = ray.direction(kx) * sz, sy = ray.direction(ky) * sz; // sz = 1 / dkz
        double[] o = org, iv = inv;
        for (int a = 0; a < 3; a++) {
            o[a] = ray.origin(a);
            iv[a] = ray.inverseDirection(a);
        }
        double okx = o[kx], oky = o[ky], okz = o[kz];

        int stamp = mailbox.next();
        int[] box = mailbox.stamp;
        int[] nodes = this.nodes;
        int[] refs = this.refs;
        double[] c = corners;
        int sp = 0, node = 0;
        double curMin = scene.enter, curMax = scene.exit;
        // The slack-widened bounds, updated only when the interval changes (not per node).
        double lo = curMin - Math.abs(curMin) * SLACK, hi = curMax + Math.abs(curMax) * SLACK;
        boolean found = false;
        while (true) {
            int w = Nodes.word(nodes, node);
            while (!Nodes.isLeaf(w, BITS)) {
                int axis = Nodes.axis(w, BITS);
                double ia = iv[axis];
                double tSplit = (Nodes.split(nodes, node) - o[axis]) * ia;
                int near = Nodes.leftChild(node), far = Nodes.rightChild(w, BITS);
                if (!(ia > 0)) { far = near; near = Nodes.rightChild(w, BITS); }
                // Traverser.decide's rule, with the widened bounds kept in lo and hi.
                if (tSplit > hi) {
                    node = near;
                } else if (tSplit < lo) {
                    node = far;
                } else {
                    stackNode[sp] = far;
                    stackMax[sp] = curMax;
                    node = near;
                    if (tSplit != tSplit) {          // the ray lies in the split plane
                        stackMin[sp] = curMin;
                    } else {
                        stackMin[sp] = tSplit;
                        curMax = tSplit;
                        hi = tSplit + Math.abs(tSplit) * SLACK;
                    }
                    sp++;
                }
                w = Nodes.word(nodes, node);
            }
            for (int r = Nodes.leafStart(nodes, node), end = r + Nodes.leafSize(w, BITS); r < end; r++) {
                int p = refs[r];
                if (box[p] == stamp) continue;
                box[p] = stamp;
                if (!TriangleIntersector.test(c, 9 * p, p, okx, oky, okz, kx, ky, kz, sx, sy, sz, tMin, tMax, hit)) continue;
                if (any) return true;
                found = true;
            }
            // Take the next saved far child that can still hold something closer.
            while (true) {
                if (sp == 0) return found;
                sp--;
                curMin = stackMin[sp];
                if (curMin <= hit.t + Math.abs(hit.t) * SLACK) break;
            }
            node = stackNode[sp];
            curMax = stackMax[sp];
            lo = curMin - Math.abs(curMin) * SLACK;
            hi = curMax + Math.abs(curMax) * SLACK;
        }
    }
}
