package org.kdtree.render;

import org.kdtree.scene.Camera;
import org.kdtree.scene.Light;
import org.kdtree.scene.Material;
import org.kdtree.scene.Scene;
import org.kdtree.scene.SceneGeometry;
import org.kdtree.scene.Vec3;
import org.kdtree.geom.Tolerance;
import java.util.List;
import org.kdtree.geom.Ray;
import org.kdtree.traverse.Hit;
import org.kdtree.traverse.RayQuery;

/**
 * Whitted ray tracing of one pixel at a time, casting only the rays the {@link EffectPlan}
 * allows. One tracer per thread: it owns its ray query, its reusable ray and hit, its sampler
 * and its ray counts.
 *
 * <p>Secondary rays start at the hit point (computed from the barycentrics, so it lies on the
 * triangle to rounding of the vertices' size) moved along the geometric normal by
 * {@link #OFFSET} times the hit's magnitude, to the side the new ray leaves on: no
 * self-intersection at any scale, and no visible gap either.
 */
public final class Tracer {
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
    private final double[] st = new double[2];

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
    }

    /** {@return the rays this tracer has cast so far} */
    public RayCounts counts() { return counts; }

    /**
     * {@return the mean radiance of pixel (x, y) over the scene's samples per pixel}
     *
     * @param x the pixel's column
     * @param y the pixel's row
     */
    public Vec3 pixel(int x, int y) {
        sampler.startPixel(x, y);
        int n = scene.samplesPerPixel();
        Camera cam = scene.camera();
        Vec3 sum = Vec3.ZERO;
        for (int i = 0; i < n; i++) {
            sampler.square(i, n, st);
            Vec3 d = cam.direction(x + st[0], y + st[1]);
            sum = sum.plus(trace(cam.eye(), d, 0, 1, RayKind.CAMERA));
        }
        return sum.times(1.0 / n);
    }

    /** Radiance arriving at {@code origin} from direction {@code -dir}; {@code weight} is the path's. */
    Vec3 trace(Vec3 origin, Vec3 dir, int depth, double weight, RayKind kind) {
        counts.add(kind);
        ray.set(origin.x(), origin.y(), origin.z(), dir.x(), dir.y(), dir.z());
        if (!query.closestHit(ray, 0, Double.POSITIVE_INFINITY, hit)) return scene.background();
        Surface s = surface(dir);
        Material m = materials.get(s.material);
        Vec3 color = m.emission().plus(scene.ambient().times(m.diffuse()));
        if (plan.lit(s.material)) color = color.plus(direct(m, s.p, s.ng, s.ns, dir.negate(), s.scale));
        if (depth >= plan.maxDepth()) return color;
        return secondary(s, m, dir, depth, weight, color);
    }

    /** What shading needs of the current hit; both normals face the incoming ray. */
    private record Surface(int material, Vec3 p, Vec3 ng, Vec3 ns, boolean entering, double scale) {
    }

    private Surface surface(Vec3 dir) {
        int tri = hit.primitive;
        Vec3 p = geometry.point(tri, hit.u, hit.v);
        Vec3 ng = geometry.geometricNormal(tri).normalized();
        Vec3 ns = geometry.shadingNormal(tri, hit.u, hit.v);
        boolean entering = ng.dot(dir) < 0;
        if (!entering) ng = ng.negate();
        if (ns.dot(ng) < 0) ns = ns.negate();
        return new Surface(geometry.materialOf(tri), p, ng, ns, entering, Math.max(p.maxAbs(), triangleMagnitude(tri)));
    }

    /** Adds to {@code color} the reflection and refraction rays the plan allows and the path's weight justifies. */
    private Vec3 secondary(Surface s, Material m, Vec3 dir, int depth, double weight, Vec3 color) {
        // near silhouettes an interpolated normal can face away from the ray: use the facet's there
        Vec3 n = dir.dot(s.ns) < 0 ? s.ns : s.ng;
        Vec3 kr = plan.reflects(s.material) ? m.reflectivity() : Vec3.ZERO;
        Vec3 kt = Vec3.ZERO;
        Vec3 refracted = null;
        if (plan.refracts(s.material)) {
            double eta = s.entering ? 1 / m.ior() : m.ior();
            refracted = refract(dir, n, eta);
            if (refracted != null) {       // else total internal reflection: kr keeps everything
                double f = m.fresnel() ? fresnel(dir, n, refracted, eta) : 0;
                if (m.fresnel()) kr = kr.times(f);
                kt = m.transmission().times(1 - f);
            }
        }
        double wr = weight * kr.max();
        if (wr >= EffectPlan.NEGLIGIBLE_WEIGHT) {
            Vec3 r = reflect(dir, n);
            if (r.dot(s.ng) <= 0) r = reflect(dir, s.ng);   // the interpolated normal bent it under the facet
            color = color.plus(kr.times(trace(leave(s.p, s.ng, r, s.scale), r, depth + 1, wr, RayKind.REFLECTION)));
        }
        double wt = weight * kt.max();
        if (refracted != null && wt >= EffectPlan.NEGLIGIBLE_WEIGHT)
            color = color.plus(kt.times(trace(leave(s.p, s.ng, refracted, s.scale), refracted, depth + 1, wt,
                    RayKind.REFRACTION)));
        return color;
    }

    /** Diffuse and Phong light from every light, with the shadow rays the plan asks for. */
    private Vec3 direct(Material m, Vec3 p, Vec3 ng, Vec3 ns, Vec3 toEye, double scale) {
        Vec3 sum = Vec3.ZERO;
        for (int li = 0; li < lights.size(); li++) {
            Light light = lights.get(li);
            boolean shadows = plan.shadowRays(li);
            if (light instanceof Light.Directional d) {
                Vec3 l = d.direction().negate().normalized();
                if (l.dot(ng) > 0 && (!shadows || visible(p, ng, l, scale, Double.POSITIVE_INFINITY)))
                    sum = sum.plus(brdf(m, ns, l, toEye).times(d.color()));
            } else if (light instanceof Light.Point pt) {
                sum = sum.plus(fromPoint(m, p, ng, ns, toEye, scale, pt.position(), pt.color(), shadows));
            } else if (light instanceof Light.Area a) {
                int n = plan.lightSamples(li);
                Vec3 each = a.color().times(1.0 / n);
                for (int i = 0; i < n; i++) {
                    sampler.square(i, n, st);
                    Vec3 q = a.pointAt(st[0], st[1]);
                    double cosLight = a.normal().dot(p.minus(q).normalized());
                    if (cosLight > 0)
                        sum = sum.plus(fromPoint(m, p, ng, ns, toEye, scale, q, each.times(cosLight), shadows));
                }
            }
        }
        return sum;
    }

    private Vec3 fromPoint(Material m, Vec3 p, Vec3 ng, Vec3 ns, Vec3 toEye, double scale, Vec3 q, Vec3 color,
                           boolean shadows) {
        Vec3 toLight = q.minus(p);
        double d2 = toLight.dot(toLight);
        Vec3 l = toLight.times(1 / Math.sqrt(d2));
        if (l.dot(ng) <= 0 || d2 == 0) return Vec3.ZERO;
        if (shadows) {
            Vec3 o = leave(p, ng, l, scale);
            if (!visible(o, q.minus(o))) return Vec3.ZERO;
        }
        return brdf(m, ns, l, toEye).times(color).times(1 / d2);
    }

    /** Shadow ray from p (offset) along unit l, up to tMax. */
    private boolean visible(Vec3 p, Vec3 ng, Vec3 l, double scale, double tMax) {
        Vec3 o = leave(p, ng, l, scale);
        counts.add(RayKind.SHADOW);
        ray.set(o.x(), o.y(), o.z(), l.x(), l.y(), l.z());
        return !query.anyHit(ray, 0, tMax);
    }

    /** Shadow ray from o to o + d, stopping just short of the end. */
    private boolean visible(Vec3 o, Vec3 d) {
        counts.add(RayKind.SHADOW);
        ray.set(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
        return !query.anyHit(ray, 0, SHADOW_END);
    }

    /** Lambert plus Phong for unit light direction l and unit direction to the eye. */
    private static Vec3 brdf(Material m, Vec3 n, Vec3 l, Vec3 toEye) {
        double cos = Math.max(0, n.dot(l));
        Vec3 c = m.diffuse().times(cos);
        if (!m.specular().isZero()) {
            double rv = reflect(l.negate(), n).dot(toEye);
            if (rv > 0) c = c.plus(m.specular().times(Math.pow(rv, m.shininess())));
        }
        return c;
    }

    /** The origin for a ray leaving p along dir: offset along the normal to dir's side. */
    static Vec3 leave(Vec3 p, Vec3 ng, Vec3 dir, double scale) {
        double eps = OFFSET * Math.max(scale, Double.MIN_NORMAL);
        return p.plus(ng.times(dir.dot(ng) >= 0 ? eps : -eps));
    }

    private double triangleMagnitude(int t) {
        double m = 0;
        for (int c = 0; c < 3; c++)
            for (int a = 0; a < 3; a++) m = Math.max(m, Math.abs(geometry.mesh().corner(t, c, a)));
        return m;
    }

    static Vec3 reflect(Vec3 d, Vec3 n) {
        return d.minus(n.times(2 * d.dot(n)));
    }

    /** Refraction of unit d through unit n (facing d's origin) with eta = n1 / n2, or null for total internal reflection. */
    static Vec3 refract(Vec3 d, Vec3 n, double eta) {
        double cosI = -d.dot(n);
        double k = 1 - eta * eta * (1 - cosI * cosI);
        if (k < 0) return null;
        return d.times(eta).plus(n.times(eta * cosI - Math.sqrt(k))).normalized();
    }

    /** Fresnel reflectance of an unpolarised dielectric interface. */
    static double fresnel(Vec3 d, Vec3 n, Vec3 t, double eta) {
        double cosI = -d.dot(n), cosT = -t.dot(n);
        double rs = (eta * cosI - cosT) / (eta * cosI + cosT);
        double rp = (eta * cosT - cosI) / (eta * cosT + cosI);
        return Math.min(1, 0.5 * (rs * rs + rp * rp));
    }
}
