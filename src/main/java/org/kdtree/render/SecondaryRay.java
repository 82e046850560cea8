package org.kdtree.render;

/**
 * A reflection or refraction ray a hit sends on (one of a {@link Shading}'s records): where it
 * starts and goes, the weight its colour adds with, and the path's weight down to it.
 */
final class SecondaryRay {
    /** Reflection or refraction. */
    final RayKind kind;
    /** Whether the ray is followed: the plan allows it and its path's weight is not negligible. */
    boolean followed;
    /** Its origin (offset off the surface, to the side it leaves on) and unit direction. */
    final double[] origin = new double[3], direction = new double[3];
    /** What its colour is multiplied by, per channel, before it is added to the hit's. */
    final double[] weight = new double[3];
    /** The product of the weights from the camera down to it (its maximum over the channels). */
    double pathWeight;

    SecondaryRay(RayKind kind) {
        this.kind = kind;
    }

    /**
     * {@return its point of the ray tree, below its parent's {@code parent}}: {@code 2 parent} for
     * the reflection, {@code 2 parent + 1} for the refraction (the random streams' numbering,
     * {@link PixelSampler#startPoint}).
     *
     * @param parent the point of the ray tree of the hit that sends it
     */
    long point(long parent) {
        return kind == RayKind.REFLECTION ? 2 * parent : 2 * parent + 1;
    }
}
