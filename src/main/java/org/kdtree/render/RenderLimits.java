package org.kdtree.render;

/**
 * The render settings' allowed ranges, stated once: the scene file's fields and the command
 * line's options check against these, and say so when a value is outside.
 */
public final class RenderLimits {
    /** Image width and height, in pixels. */
    public static final int MAX_IMAGE_SIDE = 16384;
    /** Samples per pixel. */
    public static final int MAX_SAMPLES_PER_PIXEL = 4096;
    /** Reflection and refraction depth. */
    public static final int MAX_RAY_DEPTH = 64;
    /** Shadow-ray samples of one area light. */
    public static final int MAX_LIGHT_SAMPLES = 1024;

    private RenderLimits() {
    }

    /** {@code value}, if within {@code [min, max]}; otherwise an error naming {@code what}. */
    public static int check(String what, int value, int min, int max) {
        if (value < min || value > max)
            throw new IllegalArgumentException(what + " must be between " + min + " and " + max + ", got " + value);
        return value;
    }
}
