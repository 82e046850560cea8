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
import org.kdtree.geom.Tolerance;
import org.kdtree.scene.Light;
import org.kdtree.scene.Material;
import org.kdtree.scene.Scene;
import org.kdtree.scene.SceneGeometry;
import org.kdtree.scene.Vec3;

/**
 * Whitted's shading of one hit, written once for every tracer: it turns a ray's closest hit into
 * records ({@link Shading}): emitted plus ambient light; per light sample, the diffuse and Phong
 * light it brings and the shadow ray that may block it; the reflection and refraction rays, with
 * their weights (Fresnel's at glass). It casts no ray itself: the recursive tracer ({@link
 * WhittedTracer}) follows the records at once, the block tracer ({@link BlockTracer}) gathers them
 * into packets, and both sum them alike, so their pixels agree bit for bit by construction.
 * Only the rays the {@link EffectPlan} allows are recorded. Allocation-free: vectors are {@code
 * double[3]} arrays ({@link org.kdtree.scene.Vectors}), the scratch ones live only during one
 * call. One per tracer.
 *
 * <p>Secondary rays start at the hit point (computed from the barycentrics, so it lies on the
 * triangle to rounding of the vertices' size) moved along the geometric normal by {@link #OFFSET}
 * times the hit's magnitude, to the side the new ray leaves on: no self-intersection at any
 * scale, and no visible gap either.
 */
final class Shader {
    /** Relative offset of secondary ray origins ({@link Tolerance#RAY_OFFSET}). */
    static final double OFFSET = Tolerance.RAY_OFFSET;
    /** Shadow rays toward a point stop short of it ({@link Tolerance#SHADOW_SHORTFALL}), so a light's own panel does not occlude it. */
    static final double SHADOW_END = 1 - Tolerance.SHADOW_SHORTFALL;

    private final Scene scene;
    private final EffectPlan plan;
    private final SceneGeometry geometry;
    private final List<Material> materials;
    private final List<Light> lights;
    private final double[] background;
    /** Per light: the unit direction toward a directional light and its colour; an area light's edges and power per sample. */
    private final double[][] towardLight, colour, edgeU, edgeV, perSample;
    /** Per material: its diffuse colour, its specular colour (null: no highlight) and shininess, as arrays for the light's inner loop. */
    private final double[][] diffuse, specular;
    private final double[] shininess;
    /** Per light, its first slot ({@link LightSamples}: an area light has one per sample, others one); the total last. */
    private final int[] slotOf;

    /** The surface being shaded, both normals facing the incoming ray. */
    private final double[] p = new double[3], ng = new double[3], ns = new double[3];
    private int material;
    private boolean entering;
    /** The hit's magnitude: the larger of its point's and its triangle's largest coordinate. */
    private double scale;
    /** Scratch of the direct light at one hit. */
    private final double[] toEye = new double[3], term = new double[3], l = new double[3], q = new double[3],
            power = new double[3], fromLight = new double[3], o = new double[3], toEnd = new double[3],
            incoming = new double[3], mirrored = new double[3], st = new double[2];

    /**
     * A shader of {@code scene}'s hits.
     *
     * @param scene the scene
     * @param plan  which rays to record
     */
    Shader(Scene scene, EffectPlan plan) {
        this.scene = scene;
        this.plan = plan;
        this.geometry = scene.geometry();
        this.materials = scene.materials();
        this.lights = scene.lights();
        this.background = set(scene.background(), new double[3]);
        diffuse = new double[materials.size()][];
        specular = new double[materials.size()][];
        shininess = new double[materials.size()];
        for (int i = 0; i < materials.size(); i++) {
            Material m = materials.get(i);
            diffuse[i] = set(m.diffuse(), new double[3]);
            specular[i] = m.specular().isZero() ? null : set(m.specular(), new double[3]);
            shininess[i] = m.shininess();
        }
        int n = lights.size();
        towardLight = new double[n][];
        colour = new double[n][];
        edgeU = new double[n][];
        edgeV = new double[n][];
        perSample = new double[n][];
        slotOf = new int[n + 1];
        for (int li = 0; li < n; li++) {
            if (lights.get(li) instanceof Light.Directional d) {
                towardLight[li] = set(d.direction().negate().normalized(), new double[3]);
                colour[li] = set(d.color(), new double[3]);
            } else if (lights.get(li) instanceof Light.Area a) {
                edgeU[li] = set(a.edgeU(), new double[3]);
                edgeV[li] = set(a.edgeV(), new double[3]);
                perSample[li] = set(a.color().times(1.0 / plan.lightSamples(li)), new double[3]);
            }
            slotOf[li + 1] = slotOf[li] + plan.lightSamples(li);
        }
    }

    /** {@return the most light samples a hit point has: one per light, {@code samples} per area light} */
    int slots() { return slotOf[slotOf.length - 1]; }

    /**
     * {@return the depth of point {@code point} of a ray tree: 0 for the camera ray (point 1), one
     * more per reflection ({@code 2 n}) or refraction ({@code 2 n + 1}) below it}
     *
     * @param point a point of a ray tree
     */
    static int depth(long point) { return 63 - Long.numberOfLeadingZeros(point); }

    /**
     * Shades a ray's hit into {@code out}: what the hit gives, the light samples with their shadow
     * rays, and the reflection and refraction rays, with their weights.
     *
     * @param found   whether the ray hit anything
     * @param hit     its closest hit, when {@code found}
     * @param dir     the ray's unit direction
     * @param point   its point of the camera sample's ray tree (1 for the camera ray), which picks
     *                its random stream and its depth
     * @param weight  the path's weight down to it
     * @param sampler started at the camera sample ({@link PixelSampler#startSample}): the area
     *                lights' samples come from the point's stream
     * @param out     receives the records
     */
    void shade(boolean found, Hit hit, double[] dir, long point, double weight, PixelSampler sampler, Shading out) {
        out.clear();
        if (!found) {
            System.arraycopy(background, 0, out.base, 0, 3);
            return;
        }
        Material m = surface(hit, dir, out.base);
        if (plan.lit(material)) {
            out.lit = true;
            sampler.startPoint(point);
            directLight(dir, sampler, out.lights);
        }
        if (depth(point) < plan.maxDepth()) secondary(m, dir, weight, out);
    }

    /**
     * Sets the surface of the hit, both normals facing the incoming ray; writes its emitted plus
     * ambient light to {@code out} and returns its material.
     */
    private Material surface(Hit hit, double[] dir, double[] out) {
        int tri = hit.primitive;
        geometry.point(tri, hit.u, hit.v, p);
        geometry.geometricNormal(tri, ng);
        normalize(ng);
        geometry.shadingNormal(tri, hit.u, hit.v, ns);
        entering = dot(ng, dir) < 0;
        if (!entering) negate(ng);
        if (dot(ns, ng) < 0) negate(ns);
        material = geometry.materialOf(tri);
        scale = Math.max(maxAbs(p), triangleMagnitude(tri));
        Material m = materials.get(material);
        Vec3 e = m.emission(), a = scene.ambient(), kd = m.diffuse();
        out[0] = e.x() + a.x() * kd.x();
        out[1] = e.y() + a.y() * kd.y();
        out[2] = e.z() + a.z() * kd.z();
        return m;
    }

    /** Records the light samples of every light, with the shadow rays the plan asks for. */
    private void directLight(double[] dir, PixelSampler sampler, LightSamples out) {
        for (int i = 0; i < 3; i++) toEye[i] = -dir[i];
        for (int li = 0; li < lights.size(); li++) {
            Light light = lights.get(li);
            boolean shadows = plan.shadowRays(li);
            if (light instanceof Light.Directional) {
                fromDirection(towardLight[li], colour[li], shadows, slotOf[li], out);
            } else if (light instanceof Light.Point pt) {
                fromPoint(set(pt.position(), q), set(pt.color(), power), shadows, slotOf[li], out);
            } else if (light instanceof Light.Area a) {
                fromArea(a, li, shadows, sampler, out);
            }
        }
    }

    /** The light of colour {@code c} arriving from unit direction {@code toward}, when the surface faces it. */
    private void fromDirection(double[] toward, double[] c, boolean shadows, int slot, LightSamples out) {
        if (!(dot(toward, ng) > 0)) return;
        int i = out.add(slot, toward, c, 1);
        if (shadows) {
            leave(p, ng, toward, scale, o);
            out.shadowRay(i, o, toward, Double.POSITIVE_INFINITY);
        }
    }

    /** The light of area light {@code li}, sampled at the plan's number of points over its square. */
    private void fromArea(Light.Area a, int li, boolean shadows, PixelSampler sampler, LightSamples out) {
        int n = plan.lightSamples(li);
        Vec3 c = a.center(), normal = a.normal();
        double[] u = edgeU[li], v = edgeV[li], each = perSample[li];
        for (int i = 0; i < n; i++) {
            sampler.square(i, n, st);
            double su = (st[0] - 0.5) * a.size(), sv = (st[1] - 0.5) * a.size();
            q[0] = c.x() + u[0] * su + v[0] * sv;
            q[1] = c.y() + u[1] * su + v[1] * sv;
            q[2] = c.z() + u[2] * su + v[2] * sv;
            for (int k = 0; k < 3; k++) fromLight[k] = p[k] - q[k];
            normalize(fromLight);
            double cosLight = normal.x() * fromLight[0] + normal.y() * fromLight[1] + normal.z() * fromLight[2];
            if (cosLight > 0) {
                for (int k = 0; k < 3; k++) power[k] = each[k] * cosLight;
                fromPoint(q, power, shadows, slotOf[li] + i, out);
            }
        }
    }

    /** The light of {@code power} at point {@code to}, falling off with the squared distance, when the surface faces it. */
    private void fromPoint(double[] to, double[] power, boolean shadows, int slot, LightSamples out) {
        for (int k = 0; k < 3; k++) l[k] = to[k] - p[k];
        double d2 = dot(l, l);
        double inv = 1 / Math.sqrt(d2);
        for (int k = 0; k < 3; k++) l[k] = l[k] * inv;
        if (dot(l, ng) <= 0 || d2 == 0) return;
        int i = out.add(slot, l, power, 1 / d2);
        if (shadows) {
            leave(p, ng, l, scale, o);
            for (int k = 0; k < 3; k++) toEnd[k] = to[k] - o[k];
            out.shadowRay(i, o, toEnd, SHADOW_END);
        }
    }

    /**
     * Writes to {@code out} the light that sample {@code i} of the last hit {@link #shade}d brings
     * to the eye: Lambert plus Phong for its direction, times its power and its falloff. Valid
     * until the next {@link #shade}; a tracer asks for it only once it knows the sample's shadow
     * ray reaches the light (or, keeping samples aside, for every sample).
     *
     * @param samples the last hit's light samples ({@link Shading#lights})
     * @param i       one of them
     * @param out     receives the red, green and blue light
     */
    void reflected(LightSamples samples, int i, double[] out) {
        for (int k = 0; k < 3; k++) l[k] = samples.toward(i, k);
        brdf(ns, l, term);
        double falloff = samples.falloff(i);
        out[0] = term[0] * samples.power(i, 0) * falloff;
        out[1] = term[1] * samples.power(i, 1) * falloff;
        out[2] = term[2] * samples.power(i, 2) * falloff;
    }

    /**
     * Lambert plus Phong for the surface's material, unit light direction {@code light} and the
     * unit direction to the eye, into {@code out}.
     */
    private void brdf(double[] n, double[] light, double[] out) {
        double cos = Math.max(0, dot(n, light));
        double[] kd = diffuse[material], ks = specular[material];
        out[0] = kd[0] * cos;
        out[1] = kd[1] * cos;
        out[2] = kd[2] * cos;
        if (ks != null) {
            for (int k = 0; k < 3; k++) incoming[k] = -light[k];
            reflect(incoming, n, mirrored);
            double rv = dot(mirrored, toEye);
            if (rv > 0) {
                double highlight = Math.pow(rv, shininess[material]);
                out[0] = out[0] + ks[0] * highlight;
                out[1] = out[1] + ks[1] * highlight;
                out[2] = out[2] + ks[2] * highlight;
            }
        }
    }

    /** Records the reflection and refraction rays the plan allows and the path's weight justifies. */
    private void secondary(Material m, double[] dir, double weight, Shading out) {
        SecondaryRay r = out.reflection, t = out.refraction;
        // near silhouettes an interpolated normal can face away from the ray: use the facet's there
        double[] n = dot(dir, ns) < 0 ? ns : ng;
        set(plan.reflects(material) ? m.reflectivity() : Vec3.ZERO, r.weight);
        set(Vec3.ZERO, t.weight);
        boolean refracted = false;
        if (plan.refracts(material)) {
            double eta = entering ? 1 / m.ior() : m.ior();
            refracted = refract(dir, n, eta, t.direction);
            if (refracted) {       // else total internal reflection: the reflection keeps everything
                double f = m.fresnel() ? fresnel(dir, n, t.direction, eta) : 0;
                if (m.fresnel()) for (int i = 0; i < 3; i++) r.weight[i] = r.weight[i] * f;
                set(m.transmission(), t.weight);
                for (int i = 0; i < 3; i++) t.weight[i] = t.weight[i] * (1 - f);
            }
        }
        r.pathWeight = weight * max(r.weight);
        if (r.pathWeight >= EffectPlan.NEGLIGIBLE_WEIGHT) {
            reflect(dir, n, r.direction);
            if (dot(r.direction, ng) <= 0) reflect(dir, ng, r.direction);   // the interpolated normal bent it under the facet
            leave(p, ng, r.direction, scale, r.origin);
            r.followed = true;
        }
        t.pathWeight = weight * max(t.weight);
        if (refracted && t.pathWeight >= EffectPlan.NEGLIGIBLE_WEIGHT) {
            leave(p, ng, t.direction, scale, t.origin);
            t.followed = true;
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
