package org.kdtree.render;

import java.util.Arrays;
import org.kdtree.accel.Hit;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayPacket;
import org.kdtree.scene.Scene;

/**
 * Whitted ray tracing of a block of at most {@link #SIZE} pixels at a time, breadth first, its rays
 * in packets: per camera sample, the block's ray trees ({@link RayTree}) level by level. The camera
 * rays go as packets (one per octant of directions: {@link OctantPackets}); each hit is shaded by
 * the {@link Shader}, its light samples kept with their shadow rays ({@link Shadows}) and its
 * reflection and refraction rays added to the next level; each level's rays go as packets in turn;
 * then the shadow rays of every level's hits go as packets, and each node's colour is summed,
 * children before parents, as {@link Shading} says. Each pixel so gets the colour, bit for bit,
 * and the rays that the recursive tracer ({@link WhittedTracer}) gives it.
 *
 * <p>A block keeps at most {@code shadowBudget} light samples aside (nodes of its ray trees times
 * slots per node, about 90 bytes each): past that, a tree's further reflection and refraction rays
 * are traced depth first where they arise, by the recursive tracer, so that deep trees of glass
 * and mirrors under many light samples stay within a few megabytes. Arrays made once per tracer,
 * grown to the largest trees a block has needed: nothing is allocated per block.
 */
final class BlockTracer {
    /** The most pixels a block holds: one packet of camera rays. */
    static final int SIZE = RayPacket.CAPACITY;

    private final Scene scene;
    private final Shader shader;
    private final WhittedTracer depthFirst;
    private final RayCounts counts;
    private final PixelSampler sampler;
    private final double[] cameraDir = new double[3], dir = new double[3], colour = new double[3];
    private final Hit hit = new Hit();
    private final Shading shading = new Shading(new LightSamples());
    private final RayTree tree = new RayTree();
    private final Shadows shadows;
    /** A level's rays gathered into packets, each ray's closest hit recorded as its node's. */
    private final OctantPackets level;
    /** The most nodes its ray trees keep; past them, rays are traced depth first. */
    private final int maxNodes;
    /** The camera samples per pixel of the last block. */
    private int samples;
    /** Per kind of ray, per pixel: the rays cast for it. */
    private final int[][] rays = new int[RayKind.values().length][SIZE];
    /** The rays counted, per kind, before a ray tree was finished depth first. */
    private final long[] before = new long[RayKind.values().length];
    /** Per pixel (3 each): the sum of its samples' colours. */
    private final double[] sum = new double[3 * SIZE];
    /** The block's pixels (row by row indices) in the order its packets take them ({@link RayPacket#tileOrder}). */
    private final int[] order = new int[SIZE];

    /**
     * A block tracer for one thread.
     *
     * @param scene        the scene
     * @param shader       shades its hits
     * @param query        traces this thread's packets
     * @param depthFirst   traces the rays past the budget, counting them in {@code counts} too
     * @param counts       counts the rays cast
     * @param shadowBudget the most light samples a block keeps aside
     */
    BlockTracer(Scene scene, Shader shader, PacketQuery query, WhittedTracer depthFirst, RayCounts counts, int shadowBudget) {
        this.scene = scene;
        this.shader = shader;
        this.depthFirst = depthFirst;
        this.counts = counts;
        this.sampler = new PixelSampler(scene);
        int slots = shader.slots();
        this.maxNodes = Math.max(SIZE, shadowBudget / Math.max(1, slots));
        shadows = new Shadows(query, slots);
        level = new OctantPackets(query, false, (p, at) -> {
            for (int r = 0, n = p.size(); r < n; r++) tree.record(at[r], p, r);
        });
    }

    /**
     * Traces the pixels {@code [x0, x1) x [y0, y1)} (at most {@link #SIZE}, row by row) together:
     * for each camera sample index, the block's ray trees breadth first. {@link #colour} and {@link
     * #rays} read the results.
     *
     * @param x0 the block's first column
     * @param y0 its first row
     * @param x1 one past its last column
     * @param y1 one past its last row
     */
    void block(int x0, int y0, int x1, int y1) {
        int n = scene.samplesPerPixel(), w = x1 - x0, pixels = w * (y1 - y0);
        for (int[] r : rays) Arrays.fill(r, 0, pixels, 0);
        Arrays.fill(sum, 0, 3 * pixels, 0);
        RayPacket.tileOrder(w, y1 - y0, w, order);
        for (int si = 0; si < n; si++) {
            tree.clear();
            for (int j = 0; j < pixels; j++) {
                int i = order[j];
                sampler.startCameraSample(x0 + i % w, y0 + i / w, si, n, cameraDir);
                add(i, 1, 1, sampler.eye(), cameraDir);
            }
            for (int from = 0, to; from < tree.size(); from = to) {      // level by level: each level's rays as packets, then its hits shaded
                to = tree.size();
                trace(from, to);
                for (int node = from; node < to; node++) if (!tree.finished[node]) shade(node, x0, y0, w, si);
            }
            sumColours();
        }
        samples = n;
    }

    /**
     * Writes the colour of pixel {@code i} of the last {@link #block} to {@code rgb}.
     *
     * @param i   the pixel's index in the block (row by row)
     * @param rgb receives the linear red, green and blue radiance
     */
    void colour(int i, double[] rgb) {
        double mean = 1.0 / samples;
        rgb[0] = sum[3 * i] * mean;
        rgb[1] = sum[3 * i + 1] * mean;
        rgb[2] = sum[3 * i + 2] * mean;
    }

    /**
     * {@return the rays of {@code kind} the last {@link #block} cast for its pixel {@code i}}
     *
     * @param kind a kind of ray
     * @param i    the pixel's index in the block
     */
    int rays(RayKind kind, int i) {
        return rays[kind.ordinal()][i];
    }

    /** Adds a ray to the tree, with room for its light samples (none kept yet); returns its node. */
    private int add(int pixel, long point, double weight, double[] o, double[] d) {
        int n = tree.add(pixel, point, weight, o, d);
        shadows.ensure(n + 1);
        shadows.clear(n);
        return n;
    }

    /** Traces the rays of nodes {@code from .. to - 1} as packets, recording each closest hit. */
    private void trace(int from, int to) {
        RayColumns r = tree.ray;
        for (int n = from; n < to; n++)
            if (!tree.finished[n]) level.add(r.ox[n], r.oy[n], r.oz[n], r.dx[n], r.dy[n], r.dz[n], Double.POSITIVE_INFINITY, n);
        level.flush();
    }

    /**
     * Shades node {@code node}'s hit, for pixel {@code i % w, i / w} of the block at {@code (x0,
     * y0)}, camera sample {@code si}: keeps what it gives, its light samples with their shadow rays,
     * and adds its reflection and refraction rays to the tree.
     */
    private void shade(int node, int x0, int y0, int w, int si) {
        int i = tree.pixel[node], x = x0 + i % w, y = y0 + i / w;
        count(tree.kind(node), i, 1);
        hit.primitive = tree.primitive[node];
        hit.t = tree.t[node];
        hit.u = tree.u[node];
        hit.v = tree.v[node];
        dir[0] = tree.ray.dx[node];
        dir[1] = tree.ray.dy[node];
        dir[2] = tree.ray.dz[node];
        sampler.startSample(x, y, si);
        shader.shade(hit.primitive >= 0, hit, dir, tree.point[node], tree.weight[node], sampler, shading);
        System.arraycopy(shading.base, 0, tree.base, 3 * node, 3);
        if (shading.lit) {
            tree.lit[node] = true;
            shadows.keep(node, shading.lights, shader);
            count(RayKind.SHADOW, i, shading.lights.shadowRays());
        }
        addChild(node, shading.reflection, x, y, si);
        addChild(node, shading.refraction, x, y, si);
    }

    /**
     * Adds to the tree node {@code parent}'s secondary ray {@code r}, when followed, and keeps its
     * weight: to be traced with the next level, or, past the block's node budget, traced now,
     * depth first, and kept as a finished node.
     */
    private void addChild(int parent, SecondaryRay r, int x, int y, int si) {
        if (!r.followed) return;
        long point = r.point(tree.point[parent]);
        boolean now = tree.size() >= maxNodes;
        int pixel = tree.pixel[parent], child = add(pixel, point, r.pathWeight, r.origin, r.direction);
        if (now) {
            for (RayKind k : RayKind.values()) before[k.ordinal()] = counts.get(k);
            depthFirst.trace(x, y, si, r.origin, r.direction, point, r.pathWeight, r.kind, colour);
            for (RayKind k : RayKind.values()) rays[k.ordinal()][pixel] += (int) (counts.get(k) - before[k.ordinal()]);
            tree.finish(child, colour);
        }
        tree.link(parent, child, r);
    }

    /** Counts {@code n} rays of {@code kind}, for the block's pixel {@code i} too. */
    private void count(RayKind kind, int i, int n) {
        counts.add(kind, n);
        rays[kind.ordinal()][i] += n;
    }

    /** Traces the shadow rays, sums every node's colour and adds each camera ray's to its pixel's sum. */
    private void sumColours() {
        shadows.trace(0, tree.size());
        tree.colour(shadows);
        for (int n = 0; n < tree.size() && tree.point[n] == 1; n++) {
            int b = 3 * tree.pixel[n], c = 3 * n;
            sum[b] = sum[b] + tree.colour[c];
            sum[b + 1] = sum[b + 1] + tree.colour[c + 1];
            sum[b + 2] = sum[b + 2] + tree.colour[c + 2];
        }
    }
}
