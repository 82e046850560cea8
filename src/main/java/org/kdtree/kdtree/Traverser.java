package org.kdtree.kdtree;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.kdtree.accel.Hit;
import org.kdtree.accel.Intersector;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.SlabClip;
import org.kdtree.accel.TraversalListener;
import org.kdtree.accel.TraversalStack;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Box;
import org.kdtree.geom.Ray;
import org.kdtree.geom.Tolerance;

/**
 * Ray queries on a {@link KdTree}: the talk's Algorithm 2 (stack-based near/far traversal with
 * tMin, tMax and tSplit, no recursion), made robust as Havran's thesis asks. See
 * docs/traversal.md for the case analysis; in short:
 * <ul>
 * <li>near and far come from the sign of the inverse direction, so a +0.0 or -0.0 component
 * (inverse +-infinity) gives tSplit = +-infinity and the right single child;</li>
 * <li>a ray lying exactly in the split plane (tSplit = 0 * infinity = NaN) visits both children,
 * each over the whole interval: a primitive touching the plane from either side can be hit
 * there;</li>
 * <li>intervals are closed, and ties (tSplit == tMin or tMax, within a relative slack of 2^-46,
 * about 1.4e-14, {@link Tolerance#TRAVERSAL_SLACK}, that covers rounding) visit both children, so
 * a hit exactly on a plane or at a voxel edge is never lost;</li>
 * <li>primitives are tested against the caller's whole range, not the leaf's: a hit beyond the
 * current leaf is kept as a candidate and the search continues; a saved far child is skipped only
 * when it starts beyond the closest hit so far. With mailboxing (each primitive tested once per
 * ray) this finds exactly the closest hit among the primitives of the visited leaves.</li>
 * </ul>
 *
 * <p>An instance keeps per-ray scratch state (stack, mailbox) and allocates nothing per ray in
 * {@link #closestHit} and {@link #anyHit}: use one instance per thread (the tree and the
 * intersector are shared). Over a triangle mesh without a listener, the queries run
 * a specialised 3-D loop with the triangle test inlined; every other case runs the generic
 * k-dimensional loop, which reports each step to a {@link TraversalListener}.
 */
public final class Traverser implements RayQuery {
    /** Relative slack on interval comparisons ({@link Tolerance#TRAVERSAL_SLACK}). */
    static final double SLACK = Tolerance.TRAVERSAL_SLACK;

    private static final int CLOSEST = 0, ANY = 1, ALL = 2;

    private final KdTree tree;
    private final Intersector prims;
    /** The tree's nodes, read with {@link Nodes}. */
    private final int[] nodes;
    /** The tree's {@link KdTree#axisBits()}, which {@link Nodes} decodes a word with. */
    private final int bits;
    private final int[] refs;
    /** The scene box: k minima, then k maxima ({@link #clip}'s form). */
    private final double[] scene;
    /** Where the ray enters and leaves the scene box, from {@link #clipToScene}. */
    private final double[] interval = new double[2];
    private final Mailbox mailbox;
    private final TraversalStack stack;
    private final MeshTraversal fast;
    private final Hit scratch = new Hit();
    /** The ray's range clipped to the scene box, from {@link #clipToScene}. */
    private double enter, exit;

    /**
     * A traverser of {@code tree} over the primitives it was built over.
     *
     * @param tree the tree
     * @throws IllegalArgumentException if it was built over points, which no ray is traced against
     */
    public Traverser(KdTree tree) {
        this.tree = tree;
        this.prims = tree.intersector();
        nodes = tree.nodes;
        bits = tree.axisBits();
        refs = tree.refs;
        Box b = tree.bounds();
        int k = b.dimension();
        scene = new double[2 * k];
        for (int a = 0; a < k; a++) {
            scene[a] = b.min(a);
            scene[k + a] = b.max(a);
        }
        mailbox = new Mailbox(prims.size());
        int depth = tree.stats().maxDepth() + 2;
        stack = new TraversalStack(depth);
        fast = prims instanceof TriangleIntersector ? new MeshTraversal(tree, mailbox, depth) : null;
    }

    /** {@return the tree} */
    public KdTree tree() { return tree; }
    /** {@return the intersector for the tree's primitives} */
    public Intersector intersector() { return prims; }

    @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) {
        if (fast != null) return fast.closestHit(ray, tMin, tMax, hit);
        return closestHit(ray, tMin, tMax, hit, TraversalListener.NONE);
    }

    /**
     * {@link #closestHit(Ray, double, double, Hit)}, reporting each step to {@code listener}.
     *
     * @param ray the ray
     * @param tMin the start of the ray's range
     * @param tMax the end of the ray's range
     * @param hit receives the closest hit
     * @param listener is told each step
     * @return whether the ray hit a primitive
     */
    public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit, TraversalListener listener) {
        hit.reset();
        boolean found = trace(CLOSEST, ray, tMin, tMax, hit, null, listener);
        listener.end(found, hit);
        return found;
    }

    @Override public boolean anyHit(Ray ray, double tMin, double tMax) {
        if (fast != null) return fast.anyHit(ray, tMin, tMax);
        return anyHit(ray, tMin, tMax, TraversalListener.NONE);
    }

    /**
     * {@link #anyHit(Ray, double, double)}, reporting each step to {@code listener}.
     *
     * @param ray the ray
     * @param tMin the start of the ray's range
     * @param tMax the end of the ray's range
     * @param listener is told each step
     * @return whether the ray hit a primitive
     */
    public boolean anyHit(Ray ray, double tMin, double tMax, TraversalListener listener) {
        boolean found = trace(ANY, ray, tMin, tMax, scratch.reset(), null, listener);
        listener.end(found, scratch);
        return found;
    }

    /**
     * Every intersection with {@code tMin <= t <= tMax}, one per primitive hit (its closest point
     * in the range), sorted by t (ties by primitive). Allocates the list: for the workbench, not
     * for hot loops.
     * @param ray the ray
     * @param tMin the start of the ray's range
     * @param tMax the end of the ray's range
     * @return the hits
     */
    public List<Hit> allHits(Ray ray, double tMin, double tMax) {
        return allHits(ray, tMin, tMax, TraversalListener.NONE);
    }

    /**
     * {@link #allHits(Ray, double, double)}, reporting each step to {@code listener}.
     *
     * @param ray the ray
     * @param tMin the start of the ray's range
     * @param tMax the end of the ray's range
     * @param listener is told each step
     * @return the hits
     */
    public List<Hit> allHits(Ray ray, double tMin, double tMax, TraversalListener listener) {
        List<Hit> all = new ArrayList<>();
        trace(ALL, ray, tMin, tMax, scratch.reset(), all, listener);
        all.sort(Comparator.<Hit>comparingDouble(h -> h.t).thenComparingInt(h -> h.primitive));
        listener.end(!all.isEmpty(), scratch.reset());
        return all;
    }

    /** The generic loop: Algorithm 2 over any dimension and any intersector. */
    private boolean trace(int mode, Ray ray, double tMin, double tMax, Hit hit, List<Hit> all, TraversalListener l) {
        checkRay(ray);
        if (!clipToScene(ray, tMin, tMax)) {
            l.missedScene();
            return false;
        }
        l.begin(enter, exit);
        int stamp = mailbox.next();
        boolean found = false;
        stack.clear();
        int node = 0;
        double curMin = enter, curMax = exit;
        while (true) {
            int w = Nodes.word(nodes, node);
            while (!Nodes.isLeaf(w, bits)) {
                int axis = Nodes.axis(w, bits), far = Nodes.rightChild(w, bits), near = Nodes.leftChild(node);
                double inv = ray.inverseDirection(axis), xi = Nodes.split(nodes, node);
                double tSplit = (xi - ray.origin(axis)) * inv;
                if (!(inv > 0)) { far = near; near = Nodes.rightChild(w, bits); }
                TraversalListener.Visit visit = decide(tSplit, curMin, curMax);
                l.interior(node, axis, xi, curMin, curMax, tSplit, near, far, visit);
                switch (visit) {
                    case NEAR -> node = near;
                    case FAR -> node = far;
                    case BOTH_IN_PLANE -> { stack.push(far, curMin, curMax, l); node = near; }
                    case BOTH -> { stack.push(far, tSplit, curMax, l); node = near; curMax = tSplit; }
                }
                w = Nodes.word(nodes, node);
            }
            int count = Nodes.leafSize(w, bits);
            l.leaf(node, curMin, curMax, count);
            int result = visitLeaf(Nodes.leafStart(nodes, node), count, stamp, mode, ray, tMin, tMax, hit, all, l);
            if (result == ANY) return true;
            found |= result == CLOSEST;
            // Take the next saved far child that can still hold something closer.
            if (!stack.popNext(mode == CLOSEST, hit.t, SLACK, l)) return found;
            node = stack.node();
            curMin = stack.tMin();
            curMax = stack.tMax();
        }
    }

    /** Clips {@code [tMin, tMax]} to the scene box into {@link #enter} and {@link #exit}; false when nothing is left. */
    private boolean clipToScene(Ray ray, double tMin, double tMax) {
        boolean in = SlabClip.clip(ray, scene, 0, tMin, tMax, interval);
        enter = interval[0];
        exit = interval[1];
        return in;
    }

    /** Which children to visit: Algorithm 2's three cases, closed and with slack, plus the in-plane case. */
    static TraversalListener.Visit decide(double tSplit, double tMin, double tMax) {
        if (tSplit > tMax + Math.abs(tMax) * SLACK) return TraversalListener.Visit.NEAR;
        if (tSplit < tMin - Math.abs(tMin) * SLACK) return TraversalListener.Visit.FAR;
        if (tSplit != tSplit) return TraversalListener.Visit.BOTH_IN_PLANE; // 0 * infinity: the ray lies in the plane
        return TraversalListener.Visit.BOTH;
    }

    /**
     * Tests a leaf's primitives (each once per ray) against the caller's whole range. Returns
     * {@code ANY} when an any-hit query can stop, {@code CLOSEST} when something was hit, else -1.
     */
    private int visitLeaf(int first, int count, int stamp, int mode, Ray ray, double tMin, double tMax, Hit hit,
                          List<Hit> all, TraversalListener l) {
        int[] box = mailbox.stamp;
        int result = -1;
        for (int r = first; r < first + count; r++) {
            int p = refs[r];
            if (box[p] == stamp) { l.mailboxed(p); continue; }
            box[p] = stamp;
            if (mode == ALL) hit.reset();
            boolean h = prims.intersect(p, ray, tMin, tMax, hit);
            l.primitive(p, h, h ? hit.t : Double.NaN);
            if (!h) continue;
            if (mode == ANY) return ANY;
            if (mode == ALL) all.add(copy(hit));
            result = CLOSEST;
        }
        return result;
    }

    private static Hit copy(Hit h) {
        Hit c = new Hit();
        c.primitive = h.primitive;
        c.t = h.t;
        c.u = h.u;
        c.v = h.v;
        return c;
    }

    /** Rejects rays that no query can answer: non-finite values or an all-zero direction. */
    void checkRay(Ray ray) {
        ray.requireTraceable(scene.length / 2, "tree");
    }
}
