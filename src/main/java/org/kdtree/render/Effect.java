package org.kdtree.render;

/** The optical effects a render may simulate; the {@link EffectPlan} picks those a scene calls for. */
enum Effect {
    /** Light from the scene's lights (diffuse and Phong terms). */
    DIRECT_LIGHT,
    /** Phong highlights. */
    SPECULAR_HIGHLIGHTS,
    /** Shadow rays toward lights that something could occlude. */
    SHADOWS,
    /** Several shadow-ray samples over an area light. */
    SOFT_SHADOWS,
    /** Mirror reflection rays. */
    REFLECTION,
    /** Refraction rays through transparent materials. */
    REFRACTION,
    /** Fresnel weighting of reflection against refraction. */
    FRESNEL,
    /** Emitting surfaces (seen directly or in reflections; they do not light others). */
    EMISSION,
    /** Several jittered camera rays per pixel. */
    ANTIALIASING;

    /** {@return the effect's name in lower case with spaces, for reports} */
    public String label() { return name().toLowerCase(java.util.Locale.ROOT).replace('_', ' '); }
}
