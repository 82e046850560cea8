package org.kdtree.scene;

/**
 * A surface: Lambertian colour, optional Phong highlight, optional mirror reflection and
 * optional glass (refraction with Fresnel). The scene format's material types are presets of
 * this one record; MTL {@code illum} models map onto it as well (see {@code io.MaterialReader}).
 *
 * @param name         for reports
 * @param diffuse      Lambertian reflectance (kd)
 * @param specular     Phong highlight colour (ks); zero for none
 * @param shininess    Phong exponent (ns)
 * @param reflectivity mirror reflectance (kr); zero for no reflection rays
 * @param transmission colour filter of light refracted through glass; zero for no refraction rays
 * @param ior          index of refraction of glass
 * @param fresnel      whether reflection and transmission follow Fresnel's equations for a
 *                     dielectric (scaling reflectivity by F and transmission by 1 - F), else
 *                     reflectivity and transmission are used as they are
 * @param lit          whether lights shade the surface at all (MTL illum 0 is unlit: no shadow rays)
 * @param emission     emitted radiance, seen directly and in reflections (light panels)
 */
public record Material(String name, Vec3 diffuse, Vec3 specular, double shininess, Vec3 reflectivity,
                       Vec3 transmission, double ior, boolean fresnel, boolean lit, Vec3 emission) {

    /**
     * {@return a Lambertian material}
     *
     * @param name for reports
     * @param color the diffuse colour
     */
    public static Material diffuse(String name, Vec3 color) {
        return new Material(name, color, Vec3.ZERO, 1, Vec3.ZERO, Vec3.ZERO, 1, false, true, Vec3.ZERO);
    }

    /**
     * {@return a Lambertian material with a Phong highlight}
     *
     * @param name for reports
     * @param color the diffuse colour
     * @param specular the highlight colour
     * @param shininess the Phong exponent
     */
    public static Material phong(String name, Vec3 color, Vec3 specular, double shininess) {
        return new Material(name, color, specular, shininess, Vec3.ZERO, Vec3.ZERO, 1, false, true, Vec3.ZERO);
    }

    /**
     * {@return a mirror over a diffuse colour}
     *
     * @param name for reports
     * @param color the diffuse colour
     * @param reflectivity the mirror reflectance
     */
    public static Material mirror(String name, Vec3 color, Vec3 reflectivity) {
        return new Material(name, color, Vec3.ZERO, 1, reflectivity, Vec3.ZERO, 1, false, true, Vec3.ZERO);
    }

    /**
     * {@return clear glass}: transmits and reflects by Fresnel, a faint highlight from the lights.
     *
     * @param name for reports
     * @param tint the colour filter of refracted light
     * @param ior the index of refraction
     */
    public static Material glass(String name, Vec3 tint, double ior) {
        return new Material(name, Vec3.ZERO, new Vec3(0.5, 0.5, 0.5), 200, Vec3.ONE, tint, ior, true, true, Vec3.ZERO);
    }

    /**
     * {@return this material emitting {@code e}}
     *
     * @param e the emitted radiance
     */
    public Material withEmission(Vec3 e) {
        return new Material(name, diffuse, specular, shininess, reflectivity, transmission, ior, fresnel, lit, e);
    }

    /** {@return whether rays leave this surface by reflection} */
    public boolean reflects() { return !reflectivity.isZero(); }

    /** {@return whether rays pass through this surface by refraction} */
    public boolean refracts() { return !transmission.isZero(); }

    /** {@return whether the lights' direct contribution can be non-zero here} (so shadow rays may be needed). */
    public boolean needsLights() { return lit && (!diffuse.isZero() || !specular.isZero()); }
}
