package org.kdtree.scene;

import org.kdtree.limits.Limits;

/** A light source. Lights are not geometry: they are never hit by rays. */
public sealed interface Light {
    /** {@return the radiant colour} (already multiplied by any intensity). */
    Vec3 color();

    /** {@return whether the scene file allows this light to cast shadows at all} (default true). */
    boolean castsShadows();

    /** A point light; its contribution falls off with the squared distance. */
    record Point(Vec3 position, Vec3 color, boolean castsShadows) implements Light {
    }

    /** A light at infinity shining along {@code direction} (unit, from the light toward the scene). */
    record Directional(Vec3 direction, Vec3 color, boolean castsShadows) implements Light {
    }

    /**
     * A square area light, one-sided (it shines along {@code normal}), sampled at {@code samples}
     * points per shading point for soft shadows. {@code color} is its total power; each sample
     * carries {@code color / samples}, falling off with the squared distance and the cosine at the light.
     */
    record Area(Vec3 center, Vec3 normal, double size, int samples, Vec3 color, boolean castsShadows)
            implements Light {
        /**
         * Checks the number of samples.
         *
         * @param center the square's centre
         * @param normal the unit normal along which it shines
         * @param size the square's edge length
         * @param samples points sampled per shading point
         * @param color its total power
         * @param castsShadows whether it casts shadows
         */
        public Area {
            Limits.LIGHT_SAMPLES.check("samples", samples);
        }

        /**
         * {@return a unit vector in the light's plane}: the square's points are
         * center + (s - 0.5) size edgeU + (t - 0.5) size edgeV for s, t in [0, 1).
         */
        public Vec3 edgeU() {
            Vec3 a = Math.abs(normal.x()) < 0.9 ? new Vec3(1, 0, 0) : new Vec3(0, 1, 0);
            return normal.cross(a).normalized();
        }

        /** {@return the second unit vector in the light's plane} */
        public Vec3 edgeV() { return normal.cross(edgeU()); }
    }
}
