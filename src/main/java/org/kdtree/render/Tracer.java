package org.kdtree.render;

import static org.kdtree.scene.Vectors.dot;
import static org.kdtree.scene.Vectors.max;
import static org.kdtree.scene.Vectors.maxAbs;
import static org.kdtree.scene.Vectors.negate;
import static org.kdtree.scene.Vectors.normalize;
import static org.kdtree.scene.Vectors.reflect;
import static org.kdtree.scene.Vectors.set;

import java.util.List;
import org.kdtree.accel.Hit;
import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.RayQuery;
import org.kdtree.geom.Ray;
import org.kdtree.geom.Tolerance;
import org.kdtree.scene.Light;
import org.kdtree.scene.Material;
import org.kdtree.scene.Scene;
import org.kdtree.scene.SceneGeometry;
import org.kdtree.scene.Vec3;

/**
 * Whitted ray tracing of one pixel, or one block of pixels, at a time, casting only the rays the {@link EffectPlan}
 * allows. One tracer per thread: it owns its ray query, its reusable ray and hit, its sampler,
 * its ray counts and one {@link Bounce} of scratch vectors per level of the ray tree, so that
 * tracing allocates nothing: vectors are {@code double[3]} arrays ({@link org.kdtree.scene.Vectors}).
 *
 * <p>Every random number comes from a stream of its own ({@link PixelSampler}: the pixel, the
 * camera sample, the point of the ray tree), so the order rays are traced in changes nothing. With
 * a query that traces packets ({@link PacketQuery}: the BVH) the renderer hands the tracer 8 x 8
 * blocks of pixels ({@link #block}): per camera sample the block's ray trees are traced breadth
 * first ({@link RayTree}), each level's rays (the camera rays, then their reflections and
 * refractions, and so on) as packets, then the shadow rays of every hit of every level as
 * packets; each pixel gets, bit for bit, the colour {@link #pixel} gives it one ray at a time.
 *
 * <p>Secondary rays start at the hit point (computed from the barycentrics, so it lies on the
 * triangle to rounding of the vertices' size) moved along the geometric normal by
 * {@link #OFFSET} times the hit's magnitude, to the side the new ray leaves on: no
 * self-intersection at any scale, and no visible gap either.
 */
final class Tracer {
    /** Relative offset of secondary ray origins ({@link Tolerance#RAY_OFFSET}). */
    public static final double OFFSET = Tolerance.RAY_OFFSET;
    /** Shadow rays toward a point stop short of it ({@link Tolerance#SHADOW_SHORTFALL}), so a light's own panel does not occlude it. */
    private static final double SHADOW_END = 1 - Tolerance.SHADOW_SHORTFALL;

    private final Scene scene;
    private final EffectPlan plan;
    private final RayQuery query;
    private final SceneGeometry geometry;
    private final List<Material> materials;
    private final List<Light> lights;
    private final PixelSampler sampler;
    private final RayCounts counts = new RayCounts();
    private final Ray ray = new Ray(3);
    private final Hit hit = new Hit();
    /** The pixel, and its camera sample, being traced: they pick the random streams ({@link PixelSampler#start}). */
    private int px, py, ps;
    private final double[] st = new double[2];
    private final double[] eye, background;
    /** Per light: the unit direction toward a directional light; an area light's edges and power per sample. */
    private final double[][] towardLight, edgeU, edgeV, perSample;
    private final Bounce[] bounces;
    /** Per light, its first shadow-ray slot in a {@link Block} (an area light has one per sample, others one); the total last. */
    private final int[] slotOf;
    /** The most shadow rays per shaded point the packet path keeps (more: the per-pixel path, each traced alone). */
    private static final int MAX_SLOTS = 1024;
    /** The packet path's state, when the query traces packets ({@link #tracesPackets}); else null. */
    private final Block block;
    /** The pixel of the block whose rays are being counted ({@link Block#rays}), or -1 on the per-pixel path. */
    private int blockPixel = -1;
    /** The direction of the ray whose hit the packet path shades. */
    private final double[] dir = new double[3];
    /** Scratch of the direct light at one hit: never live across a recursive trace. */
    private final double[] cameraDir = new double[3], toEye = new double[3], sum = new double[3], term = new double[3],
            l = new double[3], q = new double[3], power = new double[3], o = new double[3], toEnd = new double[3],
            mirrored = new double[3];

    /**
     * The packet path's state for one block of at most {@link #SIZE} pixels ({@link Tracer#block}):
     * each camera sample's ray trees, breadth first ({@link RayTree}), their rays traced level by
     * level as packets, their direct light kept with its shadow rays ({@link Shadows}), and each
     * pixel's sum and rays. Arrays made once per tracer, grown to the largest trees a block has
     * needed: nothing is allocated per block.
     */
    private static final class Block {
        /** The most pixels a block holds: one packet of camera rays. */
        static final int SIZE = RayPacket.CAPACITY;

        final RayTree tree = new RayTree();
        final Shadows shadows;
        /** A level's rays gathered into packets, each ray's closest hit recorded as its node's. */
        final OctantPackets level;
        /** The camera samples per pixel of the last block. */
        int samples;
        /** Per kind of ray, per pixel: the rays cast for it. */
        final int[][] rays = new int[RayKind.values().length][SIZE];
        /** Per pixel (3 each): the sum of its samples' colours. */
        final double[] sum = new double[3 * SIZE];

        /** The block's pixels (row by row indices) in the order its packets take them ({@link RayPacket#tileOrder}). */
        final int[] order = new int[SIZE];

        /** The most nodes its ray trees keep ({@link #SHADOW_BUDGET}); past them, rays are traced depth first. */
        final int maxNodes;

        Block(PacketQuery query, int slots, int maxNodes) {
            this.maxNodes = maxNodes;
            shadows = new Shadows(query, slots);
            level = new OctantPackets(query, false, (p, at) -> {
                for (int r = 0, n = p.size(); r < n; r++) tree.record(at[r], p, r);
            });
        }

        /** Adds a ray to the tree, with room for its direct light (nothing kept yet); returns its node. */
        int add(int pixel, long point, double weight, double[] o, double[] d) {
            int n = tree.add(pixel, point, weight, o, d);
            shadows.ensure(n + 1);
            shadows.clear(n);
            return n;
        }

        /** Traces the rays of nodes {@code from .. to - 1} as packets, recording each closest hit. */
        void trace(int from, int to) {
            RayColumns r = tree.ray;
            for (int n = from; n < to; n++)
                if (!tree.finished[n]) level.add(r.ox[n], r.oy[n], r.oz[n], r.dx[n], r.dy[n], r.dz[n], Double.POSITIVE_INFINITY, n);
            level.flush();
        }

        /** Traces the shadow rays, sums every node's colour and adds each camera ray's to its pixel's sum. */
        void sumColours() {
            RayTree r = tree;
            shadows.trace(0, r.size());
            r.colour(shadows);
            for (int n = 0; n < r.size() && r.point[n] == 1; n++) {
                int b = 3 * r.pixel[n], c = 3 * n;
                sum[b] = sum[b] + r.colour[c];
                sum[b + 1] = sum[b + 1] + r.colour[c + 1];
                sum[b + 2] = sum[b + 2] + r.colour[c + 2];
            }
        }
    }

    /** What one level of the ray tree keeps while its reflection and refraction rays are traced. */
    private static final class Bounce {
        final double[] p = new double[3], ng = new double[3], ns = new double[3];
        final double[] color = new double[3], kr = new double[3], kt = new double[3];
        final double[] reflected = new double[3], refracted = new double[3], origin = new double[3];
        int material;
        boolean entering;
        double scale;
    }

    /**
     * A tracer for one thread.
     *
     * @param scene the scene
     * @param plan which rays to cast
     * @param query this thread's ray queries against the tree
     */
    public Tracer(Scene scene, EffectPlan plan, RayQuery query) {
        this(scene, plan, query, SHADOW_BUDGET);
    }

    /**
     * The most light samples a block keeps aside at once (nodes of its ray trees times shadow
     * slots per node: about 90 bytes each): past {@code shadowBudget / slots} nodes, a tree's
     * further reflection and refraction rays are traced depth first where they arise, as
     * {@link #pixel} traces them, so that deep trees of glass and mirrors under many light
     * samples stay within a few megabytes.
     */
    static final int SHADOW_BUDGET = 1 << 16;

    /** {@link #Tracer(Scene, EffectPlan, RayQuery)} with the block's budget of light samples kept aside (tests make it small). */
    Tracer(Scene scene, EffectPlan plan, RayQuery query, int shadowBudget) {
        this.scene = scene;
        this.plan = plan;
        this.query = query;
        this.geometry = scene.geometry();
        this.materials = scene.materials();
        this.lights = scene.lights();
        this.sampler = new PixelSampler(scene.seed());
        this.eye = set(scene.camera().eye(), new double[3]);
        this.background = set(scene.background(), new double[3]);
        int n = lights.size();
        towardLight = new double[n][];
        edgeU = new double[n][];
        edgeV = new double[n][];
        perSample = new double[n][];
        for (int li = 0; li < n; li++) {
            if (lights.get(li) instanceof Light.Directional d) {
                towardLight[li] = set(d.direction().negate().normalized(), new double[3]);
            } else if (lights.get(li) instanceof Light.Area a) {
                edgeU[li] = set(a.edgeU(), new double[3]);
                edgeV[li] = set(a.edgeV(), new double[3]);
                perSample[li] = set(a.color().times(1.0 / plan.lightSamples(li)), new double[3]);
            }
        }
        bounces = new Bounce[plan.maxDepth() + 1];
        for (int i = 0; i < bounces.length; i++) bounces[i] = new Bounce();
        slotOf = new int[n + 1];
        for (int li = 0; li < n; li++) slotOf[li + 1] = slotOf[li] + (lights.get(li) instanceof Light.Area ? plan.lightSamples(li) : 1);
        boolean packets = query instanceof PacketQuery && slotOf[n] <= MAX_SLOTS;
        block = packets ? new Block((PacketQuery) query, slotOf[n], Math.max(Block.SIZE, shadowBudget / Math.max(1, slotOf[n]))) : null;
    }

    /** {@return the rays this tracer has cast so far} */
    public RayCounts counts() { return counts; }

    /**
     * Writes the mean radiance of pixel (x, y) over the scene's samples per pixel to {@code rgb}.
     *
     * @param x the pixel's column
     * @param y the pixel's row
     * @param rgb receives the linear red, green and blue radiance
     */
    public void pixel(int x, int y, double[] rgb) {
        int n = scene.samplesPerPixel();
        double r = 0, g = 0, b = 0;
        for (int i = 0; i < n; i++) {
            cameraDirection(x, y, i, n);
            double[] c = trace(eye, cameraDir, 0, 1, RayKind.CAMERA, 1);
            r = r + c[0];
            g = g + c[1];
            b = b + c[2];
        }
        double mean = 1.0 / n;
        rgb[0] = r * mean;
        rgb[1] = g * mean;
        rgb[2] = b * mean;
    }

    /** Sets {@link #cameraDir} to pixel (x, y)'s camera sample {@code i} of {@code n}, with its jitter from the sample's own stream. */
    private void cameraDirection(int x, int y, int i, int n) {
        px = x;
        py = y;
        ps = i;
        sampler.start(x, y, i, 0);
        sampler.square(i, n, st);
        scene.camera().direction(x + st[0], y + st[1], cameraDir);
    }

    /**
     * {@return whether this tracer renders blocks of pixels with their rays in packets ({@link
     * #block}, {@link #blockColour})}: when the query traces packets ({@link PacketQuery}) and the
     * lights take at most {@link #MAX_SLOTS} shadow rays per shaded point. The image is the
     * same either way, bit for bit.
     */
    public boolean tracesPackets() {
        return block != null;
    }

    /**
     * Traces the pixels {@code [x0, x1) x [y0, y1)} (at most {@link RayPacket#CAPACITY}, row by
     * row) together, the colour of each the colour {@link #pixel} gives it: for each camera sample
     * index, the block's ray trees breadth first. The camera rays go as packets (one per octant
     * of directions); each hit is shaded with its direct light put aside per light sample and its
     * reflection and refraction rays added to the next level; each level's rays go as packets in
     * turn; then the shadow rays of all the levels' hits go as packets, and each pixel's colour is
     * summed, children before parents, in {@link #pixel}'s order. {@link #blockColour} and {@link #blockRays} read the results. Only
     * when {@link #tracesPackets}.
     *
     * @param x0 the block's first column
     * @param y0 its first row
     * @param x1 one past its last column
     * @param y1 one past its last row
     */
    public void block(int x0, int y0, int x1, int y1) {
        Block k = block;
        int n = scene.samplesPerPixel(), pixels = (x1 - x0) * (y1 - y0), w = x1 - x0;
        for (int[] r : k.rays) java.util.Arrays.fill(r, 0, pixels, 0);
        java.util.Arrays.fill(k.sum, 0, 3 * pixels, 0);
        RayPacket.tileOrder(w, y1 - y0, w, k.order);
        for (int si = 0; si < n; si++) {
            k.tree.clear();
            for (int j = 0; j < pixels; j++) {
                int i = k.order[j];
                cameraDirection(x0 + i % w, y0 + i / w, si, n);
                k.add(i, 1, 1, eye, cameraDir);
            }
            for (int from = 0, to; from < k.tree.size(); from = to) {      // level by level: each level's rays as packets, then its hits shaded
                to = k.tree.size();
                k.trace(from, to);
                for (int node = from; node < to; node++) if (!k.tree.finished[node]) shadeNode(node, x0, y0, w, si);
            }
            blockPixel = -1;
            k.sumColours();
        }
        k.samples = n;
    }

    /**
     * Writes the colour of pixel {@code i} of the last {@link #block} to {@code rgb}, as {@link #pixel} would.
     *
     * @param i   the pixel's index in the block (row by row)
     * @param rgb receives the linear red, green and blue radiance
     */
    public void blockColour(int i, double[] rgb) {
        double mean = 1.0 / block.samples;
        rgb[0] = block.sum[3 * i] * mean;
        rgb[1] = block.sum[3 * i + 1] * mean;
        rgb[2] = block.sum[3 * i + 2] * mean;
    }

    /**
     * {@return the rays of {@code kind} the last {@link #block} cast for its pixel {@code i}}
     *
     * @param kind a kind of ray
     * @param i    the pixel's index in the block
     */
    public int blockRays(RayKind kind, int i) {
        return block.rays[kind.ordinal()][i];
    }

    /** Counts a ray of {@code kind}, for the block's pixel too when on the packet path. */
    private void count(RayKind kind) {
        counts.add(kind);
        if (blockPixel >= 0) block.rays[kind.ordinal()][blockPixel]++;
    }

    /** Radiance arriving at {@code origin} from direction {@code -dir}; {@code weight} is the path's, {@code node} its point of the ray tree. Returns its bounce's colour. */
    private double[] trace(double[] origin, double[] dir, int depth, double weight, RayKind kind, long node) {
        count(kind);
        ray.set(origin[0], origin[1], origin[2], dir[0], dir[1], dir[2]);
        return shade(query.closestHit(ray, 0, Double.POSITIVE_INFINITY, hit), dir, depth, weight, node);
    }

    /** The colour of bounce {@code depth} from the ray's closest hit in {@link #hit} ({@code found}: whether there is one). */
    private double[] shade(boolean found, double[] dir, int depth, double weight, long node) {
        Bounce s = bounces[depth];
        if (!found) {
            System.arraycopy(background, 0, s.color, 0, 3);
            return s.color;
        }
        Material m = surface(s, dir, s.color, 0);
        if (plan.lit(s.material)) {
            direct(m, s, dir, node, -1);
            for (int i = 0; i < 3; i++) s.color[i] = s.color[i] + sum[i];
        }
        if (depth < plan.maxDepth()) secondary(s, m, dir, depth, weight, node, -1);
        return s.color;
    }

    /**
     * {@link #shade} of node {@code node}'s hit on the packet path, for pixel {@code i % w, i / w}
     * of the block at {@code (x0, y0)}, camera sample {@code si}: the same values, but the direct
     * light put aside per light sample with its shadow ray, and the reflection and refraction rays
     * added to the tree, for {@link RayTree#colour} to sum in {@link #shade}'s order once they
     * and the shadow rays are traced.
     */
    private void shadeNode(int node, int x0, int y0, int w, int si) {
        RayTree r = block.tree;
        int i = r.pixel[node];
        px = x0 + i % w;
        py = y0 + i / w;
        ps = si;
        blockPixel = i;
        count(r.kind(node));
        hit.primitive = r.primitive[node];
        hit.t = r.t[node];
        hit.u = r.u[node];
        hit.v = r.v[node];
        dir[0] = r.ray.dx[node];
        dir[1] = r.ray.dy[node];
        dir[2] = r.ray.dz[node];
        int b = 3 * node;
        if (hit.primitive < 0) {
            System.arraycopy(background, 0, r.base, b, 3);
            return;
        }
        Bounce s = bounces[0];
        Material m = surface(s, dir, r.base, b);
        long point = r.point[node];
        if (plan.lit(s.material)) {
            r.lit[node] = true;
            direct(m, s, dir, point, node);
        }
        int depth = r.depth(node);
        if (depth < plan.maxDepth()) secondary(s, m, dir, depth, r.weight[node], point, node);
    }

    /**
     * What shading needs of the current hit, both normals facing the incoming ray; writes its
     * emitted plus ambient light to {@code out[at .. at + 2]} and returns its material.
     */
    private Material surface(Bounce s, double[] dir, double[] out, int at) {
        int tri = hit.primitive;
        geometry.point(tri, hit.u, hit.v, s.p);
        geometry.geometricNormal(tri, s.ng);
        normalize(s.ng);
        geometry.shadingNormal(tri, hit.u, hit.v, s.ns);
        s.entering = dot(s.ng, dir) < 0;
        if (!s.entering) negate(s.ng);
        if (dot(s.ns, s.ng) < 0) negate(s.ns);
        s.material = geometry.materialOf(tri);
        s.scale = Math.max(maxAbs(s.p), triangleMagnitude(tri));
        Material m = materials.get(s.material);
        Vec3 e = m.emission(), a = scene.ambient(), kd = m.diffuse();
        out[at] = e.x() + a.x() * kd.x();
        out[at + 1] = e.y() + a.y() * kd.y();
        out[at + 2] = e.z() + a.z() * kd.z();
        return m;
    }

    /**
     * Adds to the bounce's colour the reflection and refraction rays the plan allows and the path's
     * weight justifies; for {@code aside} a node of the block's ray tree ({@link #shadeNode}),
     * adds them to the tree as its children instead, with their weights.
     */
    private void secondary(Bounce s, Material m, double[] dir, int depth, double weight, long node, int aside) {
        // near silhouettes an interpolated normal can face away from the ray: use the facet's there
        double[] n = dot(dir, s.ns) < 0 ? s.ns : s.ng;
        set(plan.reflects(s.material) ? m.reflectivity() : Vec3.ZERO, s.kr);
        set(Vec3.ZERO, s.kt);
        boolean refracted = false;
        if (plan.refracts(s.material)) {
            double eta = s.entering ? 1 / m.ior() : m.ior();
            refracted = refract(dir, n, eta, s.refracted);
            if (refracted) {       // else total internal reflection: kr keeps everything
                double f = m.fresnel() ? fresnel(dir, n, s.refracted, eta) : 0;
                if (m.fresnel()) for (int i = 0; i < 3; i++) s.kr[i] = s.kr[i] * f;
                set(m.transmission(), s.kt);
                for (int i = 0; i < 3; i++) s.kt[i] = s.kt[i] * (1 - f);
            }
        }
        double wr = weight * max(s.kr);
        if (wr >= EffectPlan.NEGLIGIBLE_WEIGHT) {
            reflect(dir, n, s.reflected);
            if (dot(s.reflected, s.ng) <= 0) reflect(dir, s.ng, s.reflected);   // the interpolated normal bent it under the facet
            leave(s.p, s.ng, s.reflected, s.scale, s.origin);
            if (aside < 0) add(s.color, s.kr, trace(s.origin, s.reflected, depth + 1, wr, RayKind.REFLECTION, 2 * node));
            else addChild(aside, true, depth, 2 * node, wr, s);
        }
        double wt = weight * max(s.kt);
        if (refracted && wt >= EffectPlan.NEGLIGIBLE_WEIGHT) {
            leave(s.p, s.ng, s.refracted, s.scale, s.origin);
            if (aside < 0) add(s.color, s.kt, trace(s.origin, s.refracted, depth + 1, wt, RayKind.REFRACTION, 2 * node + 1));
            else addChild(aside, false, depth, 2 * node + 1, wt, s);
        }
    }

    /**
     * Adds to the block's tree node {@code parent}'s reflection (or refraction) ray, the one
     * {@link #secondary} set up at {@code depth}, and keeps its weight: to be traced with the next
     * level, or, past the block's node budget, traced now, depth first, and kept as a finished node.
     */
    private void addChild(int parent, boolean reflection, int depth, long point, double weight, Bounce s) {
        RayTree r = block.tree;
        double[] dir = reflection ? s.reflected : s.refracted;
        boolean now = r.size() >= block.maxNodes;
        double[] c = now ? trace(s.origin, dir, depth + 1, weight, reflection ? RayKind.REFLECTION : RayKind.REFRACTION, point) : null;
        int child = block.add(r.pixel[parent], point, weight, s.origin, dir);
        if (now) r.finish(child, c);
        if (reflection) r.reflection[parent] = child;            // read after add: it may have grown the arrays
        else r.refraction[parent] = child;
        System.arraycopy(reflection ? s.kr : s.kt, 0, reflection ? r.kr : r.kt, 3 * parent, 3);
    }

    /** color += k * c, component by component. */
    private static void add(double[] color, double[] k, double[] c) {
        for (int i = 0; i < 3; i++) color[i] = color[i] + k[i] * c[i];
    }

    /**
     * Diffuse and Phong light from every light into {@link #sum}, with the shadow rays the plan asks
     * for; the area lights' samples drawn from the stream of the ray tree's {@code node}. For
     * {@code aside} a node of the block's ray tree, each light sample's light and shadow ray are
     * put aside in the block instead ({@link Shadows#keepLight}).
     */
    private void direct(Material m, Bounce s, double[] dir, long node, int aside) {
        for (int i = 0; i < 3; i++) {
            toEye[i] = -dir[i];
            sum[i] = 0;
        }
        sampler.start(px, py, ps, node);
        // Where the light samples and shadow rays are kept: the block's node, or nowhere (traced at once).
        Shadows keep = aside >= 0 ? block.shadows : null;
        for (int li = 0; li < lights.size(); li++) {
            Light light = lights.get(li);
            boolean shadows = plan.shadowRays(li);
            if (light instanceof Light.Directional d) {
                double[] toward = towardLight[li];
                if (keep != null && dot(toward, s.ng) > 0) {
                    if (shadows) {
                        leave(s.p, s.ng, toward, s.scale, o);
                        keep.keepShadow(slotOf[li], aside, o, toward, Double.POSITIVE_INFINITY);
                        count(RayKind.SHADOW);
                    }
                    brdf(m, s.ns, toward, term);
                    Vec3 c = d.color();
                    keep.keepLight(slotOf[li], aside, term[0] * c.x(), term[1] * c.y(), term[2] * c.z(), shadows);
                } else if (keep == null && dot(toward, s.ng) > 0 && (!shadows || visible(s, toward))) {
                    brdf(m, s.ns, toward, term);
                    Vec3 c = d.color();
                    sum[0] = sum[0] + term[0] * c.x();
                    sum[1] = sum[1] + term[1] * c.y();
                    sum[2] = sum[2] + term[2] * c.z();
                }
            } else if (light instanceof Light.Point pt) {
                fromPoint(m, s, set(pt.position(), q), set(pt.color(), power), shadows, keep, aside, slotOf[li]);
            } else if (light instanceof Light.Area a) {
                fromArea(m, s, a, li, shadows, keep, aside);
            }
        }
    }

    /** The light of area light {@code li}, sampled at the plan's number of points over its square. */
    private void fromArea(Material m, Bounce s, Light.Area a, int li, boolean shadows, Shadows keep, int at) {
        int n = plan.lightSamples(li);
        Vec3 c = a.center(), normal = a.normal();
        double[] u = edgeU[li], v = edgeV[li], each = perSample[li];
        for (int i = 0; i < n; i++) {
            sampler.square(i, n, st);
            double su = (st[0] - 0.5) * a.size(), sv = (st[1] - 0.5) * a.size();
            q[0] = c.x() + u[0] * su + v[0] * sv;
            q[1] = c.y() + u[1] * su + v[1] * sv;
            q[2] = c.z() + u[2] * su + v[2] * sv;
            for (int k = 0; k < 3; k++) o[k] = s.p[k] - q[k];
            normalize(o);
            double cosLight = normal.x() * o[0] + normal.y() * o[1] + normal.z() * o[2];
            if (cosLight > 0) {
                for (int k = 0; k < 3; k++) power[k] = each[k] * cosLight;
                fromPoint(m, s, q, power, shadows, keep, at, slotOf[li] + i);
            }
        }
    }

    /**
     * Adds to {@link #sum} the light of {@code power} at point {@code at}, falling off with the
     * squared distance; when {@code keep} is not null, puts it and its shadow ray aside there
     * as point {@code at}'s {@code slot} instead.
     */
    private void fromPoint(Material m, Bounce s, double[] to, double[] power, boolean shadows, Shadows keep, int at, int slot) {
        for (int k = 0; k < 3; k++) l[k] = to[k] - s.p[k];
        double d2 = dot(l, l);
        double inv = 1 / Math.sqrt(d2);
        for (int k = 0; k < 3; k++) l[k] = l[k] * inv;
        if (dot(l, s.ng) <= 0 || d2 == 0) return;
        if (shadows) {
            leave(s.p, s.ng, l, s.scale, o);
            for (int k = 0; k < 3; k++) toEnd[k] = to[k] - o[k];
            if (keep != null) {
                keep.keepShadow(slot, at, o, toEnd, SHADOW_END);
                count(RayKind.SHADOW);
            } else if (!visible(o, toEnd)) {
                return;
            }
        }
        brdf(m, s.ns, l, term);
        double falloff = 1 / d2;
        if (keep != null) {
            keep.keepLight(slot, at, term[0] * power[0] * falloff, term[1] * power[1] * falloff, term[2] * power[2] * falloff, shadows);
            return;
        }
        for (int k = 0; k < 3; k++) sum[k] = sum[k] + term[k] * power[k] * falloff;
    }

    /** Shadow ray from the hit (offset) along unit {@code toward}, without end (a directional light). */
    private boolean visible(Bounce s, double[] toward) {
        leave(s.p, s.ng, toward, s.scale, o);
        count(RayKind.SHADOW);
        ray.set(o[0], o[1], o[2], toward[0], toward[1], toward[2]);
        return !query.anyHit(ray, 0, Double.POSITIVE_INFINITY);
    }

    /** Shadow ray from from to from + d, stopping just short of the end. */
    private boolean visible(double[] from, double[] d) {
        count(RayKind.SHADOW);
        ray.set(from[0], from[1], from[2], d[0], d[1], d[2]);
        return !query.anyHit(ray, 0, SHADOW_END);
    }

    /** Lambert plus Phong for unit light direction {@code light} and the unit direction to the eye, into {@code out}. */
    private void brdf(Material m, double[] n, double[] light, double[] out) {
        double cos = Math.max(0, dot(n, light));
        Vec3 kd = m.diffuse(), ks = m.specular();
        out[0] = kd.x() * cos;
        out[1] = kd.y() * cos;
        out[2] = kd.z() * cos;
        if (!ks.isZero()) {
            for (int k = 0; k < 3; k++) o[k] = -light[k];
            reflect(o, n, mirrored);
            double rv = dot(mirrored, toEye);
            if (rv > 0) {
                double highlight = Math.pow(rv, m.shininess());
                out[0] = out[0] + ks.x() * highlight;
                out[1] = out[1] + ks.y() * highlight;
                out[2] = out[2] + ks.z() * highlight;
            }
        }
    }

    /** Writes to {@code out} the origin for a ray leaving p along dir: offset along the normal to dir's side. */
    static void leave(double[] p, double[] ng, double[] dir, double scale, double[] out) {
        double eps = OFFSET * Math.max(scale, Double.MIN_NORMAL);
        double e = dot(dir, ng) >= 0 ? eps : -eps;
        for (int k = 0; k < 3; k++) out[k] = p[k] + ng[k] * e;
    }

    private double triangleMagnitude(int t) {
        double m = 0;
        for (int c = 0; c < 3; c++)
            for (int a = 0; a < 3; a++) m = Math.max(m, Math.abs(geometry.mesh().corner(t, c, a)));
        return m;
    }

    /** Refraction of unit d through unit n (facing d's origin) with eta = n1 / n2 into {@code out}; false for total internal reflection. */
    static boolean refract(double[] d, double[] n, double eta, double[] out) {
        double cosI = -dot(d, n);
        double k = 1 - eta * eta * (1 - cosI * cosI);
        if (k < 0) return false;
        double along = eta * cosI - Math.sqrt(k);
        for (int i = 0; i < 3; i++) out[i] = d[i] * eta + n[i] * along;
        normalize(out);
        return true;
    }

    /** Fresnel reflectance of an unpolarised dielectric interface. */
    static double fresnel(double[] d, double[] n, double[] t, double eta) {
        double cosI = -dot(d, n), cosT = -dot(t, n);
        double rs = (eta * cosI - cosT) / (eta * cosI + cosT);
        double rp = (eta * cosT - cosI) / (eta * cosT + cosI);
        return Math.min(1, 0.5 * (rs * rs + rp * rp));
    }
}
