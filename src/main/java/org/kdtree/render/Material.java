package org.kdtree.render;

/**
 * A surface: Lambertian colour, optional Phong highlight, optional mirror reflection and
 * optional glass (refraction with Fresnel). The scene format's material types are presets of
 * this one record; MTL {@code illum} models map onto it as well (see {@code io.MtlMaterials}).
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

    public static Material diffuse(String name, Vec3 color) {
        return new Material(name, color, Vec3.ZERO, 1, Vec3.ZERO, Vec3.ZERO, 1, false, true, Vec3.ZERO);
    }

    public static Material phong(String name, Vec3 color, Vec3 specular, double shininess) {
        return new Material(name, color, specular, shininess, Vec3.ZERO, Vec3.ZERO, 1, false, true, Vec3.ZERO);
    }

    public static Material mirror(String name, Vec3 color, Vec3 reflectivity) {
        return new Material(name, color, Vec3.ZERO, 1, reflectivity, Vec3.ZERO, 1, false, true, Vec3.ZERO);
    }

    /** Clear glass: transmits and reflects by Fresnel, a faint highlight from the lights. */
    public static Material glass(String name, Vec3 tint, double ior) {
        return new Material(name, Vec3.ZERO, new Vec3(0.5, 0.5, 0.5), 200, Vec3.ONE, tint, ior, true, true, Vec3.ZERO);
    }

    public Material withEmission(Vec3 e) {
        return new Material(name, diffuse, specular, shininess, reflectivity, transmission, ior, fresnel, lit, e);
    }

    /** Whether rays leave this surface by reflection. */
    public boolean reflects() { return !reflectivity.isZero(); }

    /** Whether rays pass through this surface by refraction. */
    public boolean refracts() { return !transmission.isZero(); }

    /** Whether the lights' direct contribution can be non-zero here (so shadow rays may be needed). */
    public boolean needsLights() { return lit && (!diffuse.isZero() || !specular.isZero()); }
}
