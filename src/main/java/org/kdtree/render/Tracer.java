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
 * Whitted ray tracing of one pixel at a time, casting only the rays the {@link EffectPlan}
 * allows. One tracer per thread: it owns its ray query, its reusable ray and hit, its sampler,
 * its ray counts and one {@link Bounce} of scratch vectors per level of the ray tree, so that
 * tracing allocates nothing: vectors are {@code double[3]} arrays ({@link org.kdtree.scene.Vectors}).
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
    /** Camera rays traced together ({@link #cameraPacket}). */
    private final RayPacket packet = new RayPacket();
    private final Hit hit = new Hit();
    private final double[] st = new double[2];
    private final double[] eye, background;
    /** Per light: the unit direction toward a directional light; an area light's edges and power per sample. */
    private final double[][] towardLight, edgeU, edgeV, perSample;
    private final Bounce[] bounces;
    /** Scratch of the direct light at one hit: never live across a recursive trace. */
    private final double[] cameraDir = new double[3], toEye = new double[3], sum = new double[3], term = new double[3],
            l = new double[3], q = new double[3], power = new double[3], o = new double[3], toEnd = new double[3],
            mirrored = new double[3];

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
        sampler.startPixel(x, y);
        int n = scene.samplesPerPixel();
        double r = 0, g = 0, b = 0;
        for (int i = 0; i < n; i++) {
            sampler.square(i, n, st);
            scene.camera().direction(x + st[0], y + st[1], cameraDir);
            double[] c = trace(eye, cameraDir, 0, 1, RayKind.CAMERA);
            r = r + c[0];
            g = g + c[1];
            b = b + c[2];
        }
        double mean = 1.0 / n;
        rgb[0] = r * mean;
        rgb[1] = g * mean;
        rgb[2] = b * mean;
    }

    /**
     * {@return whether camera rays are traced in packets ({@link #cameraPacket}, {@link #packetPixel})}:
     * when the query traces packets ({@link PacketQuery}) and a pixel has one sample (its centre,
     * drawing no random number, so that every pixel's random numbers stay its own, in the same order)
     */
    public boolean tracesPackets() {
        return query instanceof PacketQuery && scene.samplesPerPixel() == 1;
    }

    /**
     * Traces the camera rays of the pixels {@code [x0, x1) x [y0, y1)} (at most
     * {@link RayPacket#CAPACITY}, row by row) as one packet; {@link #packetPixel} shades them.
     * Only when {@link #tracesPackets}.
     *
     * @param x0 the block's first column
     * @param y0 its first row
     * @param x1 one past its last column
     * @param y1 one past its last row
     */
    public void cameraPacket(int x0, int y0, int x1, int y1) {
        packet.clear();
        for (int y = y0; y < y1; y++)
            for (int x = x0; x < x1; x++) {
                scene.camera().direction(x + 0.5, y + 0.5, cameraDir);
                packet.add(eye[0], eye[1], eye[2], cameraDir[0], cameraDir[1], cameraDir[2], 0, Double.POSITIVE_INFINITY);
            }
        ((PacketQuery) query).closestHits(packet);
    }

    /**
     * Writes pixel (x, y)'s radiance to {@code rgb}, as {@link #pixel} does, from its camera ray's
     * hit in the last {@link #cameraPacket}.
     *
     * @param i   the pixel's index in the packet (row by row within the block)
     * @param x   the pixel's column
     * @param y   the pixel's row
     * @param rgb receives the linear red, green and blue radiance
     */
    public void packetPixel(int i, int x, int y, double[] rgb) {
        sampler.startPixel(x, y);
        counts.add(RayKind.CAMERA);
        cameraDir[0] = packet.dx[i];
        cameraDir[1] = packet.dy[i];
        cameraDir[2] = packet.dz[i];
        hit.primitive = packet.primitive[i];
        hit.t = packet.t[i];
        hit.u = packet.u[i];
        hit.v = packet.v[i];
        double[] c = shade(packet.found(i), cameraDir, 0, 1);
        double r = 0 + c[0], g = 0 + c[1], b = 0 + c[2];       // pixel's sum and mean over its one sample
        rgb[0] = r * 1.0;
        rgb[1] = g * 1.0;
        rgb[2] = b * 1.0;
    }

    /** Radiance arriving at {@code origin} from direction {@code -dir}; {@code weight} is the path's. Returns its bounce's colour. */
    private double[] trace(double[] origin, double[] dir, int depth, double weight, RayKind kind) {
        counts.add(kind);
        ray.set(origin[0], origin[1], origin[2], dir[0], dir[1], dir[2]);
        return shade(query.closestHit(ray, 0, Double.POSITIVE_INFINITY, hit), dir, depth, weight);
    }

    /** The colour of bounce {@code depth} from the ray's closest hit in {@link #hit} ({@code found}: whether there is one). */
    private double[] shade(boolean found, double[] dir, int depth, double weight) {
        Bounce s = bounces[depth];
        if (!found) {
            System.arraycopy(background, 0, s.color, 0, 3);
            return s.color;
        }
        surface(s, dir);
        Material m = materials.get(s.material);
        Vec3 e = m.emission(), a = scene.ambient(), kd = m.diffuse();
        s.color[0] = e.x() + a.x() * kd.x();
        s.color[1] = e.y() + a.y() * kd.y();
        s.color[2] = e.z() + a.z() * kd.z();
        if (plan.lit(s.material)) {
            direct(m, s, dir);
            for (int i = 0; i < 3; i++) s.color[i] = s.color[i] + sum[i];
        }
        if (depth < plan.maxDepth()) secondary(s, m, dir, depth, weight);
        return s.color;
    }

    /** What shading needs of the current hit; both normals face the incoming ray. */
    private void surface(Bounce s, double[] dir) {
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
    }

    /** Adds to the bounce's colour the reflection and refraction rays the plan allows and the path's weight justifies. */
    private void secondary(Bounce s, Material m, double[] dir, int depth, double weight) {
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
            add(s.color, s.kr, trace(s.origin, s.reflected, depth + 1, wr, RayKind.REFLECTION));
        }
        double wt = weight * max(s.kt);
        if (refracted && wt >= EffectPlan.NEGLIGIBLE_WEIGHT) {
            leave(s.p, s.ng, s.refracted, s.scale, s.origin);
            add(s.color, s.kt, trace(s.origin, s.refracted, depth + 1, wt, RayKind.REFRACTION));
        }
    }

    /** color += k * c, component by component. */
    private static void add(double[] color, double[] k, double[] c) {
        for (int i = 0; i < 3; i++) color[i] = color[i] + k[i] * c[i];
    }

    /** Diffuse and Phong light from every light into {@link #sum}, with the shadow rays the plan asks for. */
    private void direct(Material m, Bounce s, double[] dir) {
        for (int i = 0; i < 3; i++) {
            toEye[i] = -dir[i];
            sum[i] = 0;
        }
        for (int li = 0; li < lights.size(); li++) {
            Light light = lights.get(li);
            boolean shadows = plan.shadowRays(li);
            if (light instanceof Light.Directional d) {
                double[] toward = towardLight[li];
                if (dot(toward, s.ng) > 0 && (!shadows || visible(s, toward))) {
                    brdf(m, s.ns, toward, term);
                    Vec3 c = d.color();
                    sum[0] = sum[0] + term[0] * c.x();
                    sum[1] = sum[1] + term[1] * c.y();
                    sum[2] = sum[2] + term[2] * c.z();
                }
            } else if (light instanceof Light.Point pt) {
                fromPoint(m, s, set(pt.position(), q), set(pt.color(), power), shadows);
            } else if (light instanceof Light.Area a) {
                fromArea(m, s, a, li, shadows);
            }
        }
    }

    /** The light of area light {@code li}, sampled at the plan's number of points over its square. */
    private void fromArea(Material m, Bounce s, Light.Area a, int li, boolean shadows) {
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
                fromPoint(m, s, q, power, shadows);
            }
        }
    }

    /** Adds to {@link #sum} the light of {@code power} at point {@code at}, falling off with the squared distance. */
    private void fromPoint(Material m, Bounce s, double[] at, double[] power, boolean shadows) {
        for (int k = 0; k < 3; k++) l[k] = at[k] - s.p[k];
        double d2 = dot(l, l);
        double inv = 1 / Math.sqrt(d2);
        for (int k = 0; k < 3; k++) l[k] = l[k] * inv;
        if (dot(l, s.ng) <= 0 || d2 == 0) return;
        if (shadows) {
            leave(s.p, s.ng, l, s.scale, o);
            for (int k = 0; k < 3; k++) toEnd[k] = at[k] - o[k];
            if (!visible(o, toEnd)) return;
        }
        brdf(m, s.ns, l, term);
        double falloff = 1 / d2;
        for (int k = 0; k < 3; k++) sum[k] = sum[k] + term[k] * power[k] * falloff;
    }

    /** Shadow ray from the hit (offset) along unit {@code toward}, without end (a directional light). */
    private boolean visible(Bounce s, double[] toward) {
        leave(s.p, s.ng, toward, s.scale, o);
        counts.add(RayKind.SHADOW);
        ray.set(o[0], o[1], o[2], toward[0], toward[1], toward[2]);
        return !query.anyHit(ray, 0, Double.POSITIVE_INFINITY);
    }

    /** Shadow ray from from to from + d, stopping just short of the end. */
    private boolean visible(double[] from, double[] d) {
        counts.add(RayKind.SHADOW);
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
