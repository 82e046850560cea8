package org.kdtree.render;

/** The kinds of rays a render casts, counted separately. */
enum RayKind {
    /** From the eye through a pixel sample. */
    CAMERA,
    /** From a surface point toward a light (any-hit query). */
    SHADOW,
    /** Mirror reflection (including the Fresnel-reflected part at glass). */
    REFLECTION,
    /** Refraction into or out of glass. */
    REFRACTION;

    /** {@return the kind's name in lower case, for reports} */
    public String label() { return name().toLowerCase(java.util.Locale.ROOT); }
}
