package org.kdtree.render;

import org.kdtree.scene.Light;
import org.kdtree.scene.Material;
import org.kdtree.scene.Scene;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;

/**
 * Which effects a scene calls for, worked out before any ray is traced, and so which rays the
 * tracer casts: shadow rays only toward lights that something can occlude, reflection rays only
 * from reflective materials, refraction rays only through transparent ones, several samples
 * only for area lights, and no secondary rays at all when the depth limit is 0.
 */
public final class EffectPlan {
    /** Paths whose weight falls below this are not followed further: their effect is invisible. */
    public static final double NEGLIGIBLE_WEIGHT = 1e-3;

    private final boolean[] reflects, refracts, lit;
    private final boolean[] shadowRays;
    private final int[] lightSamples;
    private final int maxDepth;
    private final EnumSet<Effect> effects = EnumSet.noneOf(Effect.class);
    private final List<String> notes = new ArrayList<>();

    /**
     * Works out the plan for {@code scene}.
     *
     * @param scene the scene to render
     */
    public EffectPlan(Scene scene) {
        List<Material> ms = scene.materials();
        maxDepth = scene.maxDepth();
        reflects = new boolean[ms.size()];
        refracts = new boolean[ms.size()];
        lit = new boolean[ms.size()];
        boolean anyLit = false;
        for (int i = 0; i < ms.size(); i++) {
            Material m = ms.get(i);
            reflects[i] = maxDepth > 0 && m.reflects();
            refracts[i] = maxDepth > 0 && m.refracts();
            lit[i] = m.needsLights() && !scene.lights().isEmpty();
            anyLit |= lit[i];
            if (reflects[i]) effects.add(Effect.REFLECTION);
            if (refracts[i]) effects.add(Effect.REFRACTION);
            if ((reflects[i] || refracts[i]) && m.fresnel()) effects.add(Effect.FRESNEL);
            if (lit[i] && !m.specular().isZero()) effects.add(Effect.SPECULAR_HIGHLIGHTS);
            if (!m.emission().isZero()) effects.add(Effect.EMISSION);
        }
        if (anyLit) effects.add(Effect.DIRECT_LIGHT);
        else effects.remove(Effect.SPECULAR_HIGHLIGHTS);
        List<Light> lights = scene.lights();
        shadowRays = new boolean[lights.size()];
        lightSamples = new int[lights.size()];
        for (int i = 0; i < lights.size(); i++) {
            Light l = lights.get(i);
            lightSamples[i] = l instanceof Light.Area a ? a.samples() : 1;
            shadowRays[i] = anyLit && l.castsShadows() && scene.geometryMayOcclude();
            if (shadowRays[i]) effects.add(lightSamples[i] > 1 ? Effect.SOFT_SHADOWS : Effect.SHADOWS);
            if (!l.castsShadows()) notes.add("light " + i + " casts no shadows (scene file)");
        }
        if (anyLit && !scene.geometryMayOcclude() && !lights.isEmpty())
            notes.add("no shadow rays: the geometry cannot occlude itself");
        if (scene.samplesPerPixel() > 1) effects.add(Effect.ANTIALIASING);
    }

    /**
     * {@return whether rays reflect off material {@code m}}
     *
     * @param m a material index
     */
    public boolean reflects(int m) { return reflects[m]; }

    /**
     * {@return whether rays refract through material {@code m}}
     *
     * @param m a material index
     */
    public boolean refracts(int m) { return refracts[m]; }

    /**
     * {@return whether the lights shade material {@code m}}
     *
     * @param m a material index
     */
    public boolean lit(int m) { return lit[m]; }

    /**
     * {@return whether shadow rays are cast toward light {@code l}}
     *
     * @param l a light index
     */
    public boolean shadowRays(int l) { return shadowRays[l]; }

    /**
     * {@return samples per shading point on light {@code l}}: 1 except for area lights.
     *
     * @param l a light index
     */
    public int lightSamples(int l) { return lightSamples[l]; }

    /** {@return the scene's depth limit: the longest chain of secondary rays after the camera ray} */
    public int maxDepth() { return maxDepth; }

    /** {@return the effects this plan simulates} */
    public Set<Effect> effects() { return EnumSet.copyOf(effects); }

    /** {@return one line per fact, for the render summary} */
    public String describe() {
        StringBuilder s = new StringBuilder("effects: ");
        if (effects.isEmpty()) s.append("none (flat colours)");
        else effects.forEach(e -> s.append(e.label()).append(", "));
        if (!effects.isEmpty()) s.setLength(s.length() - 2);
        s.append(System.lineSeparator()).append("max depth: ").append(maxDepth)
                .append(", negligible path weight: ").append(NEGLIGIBLE_WEIGHT);
        for (String n : notes) s.append(System.lineSeparator()).append(n);
        return s.toString();
    }
}
