package org.kdtree.render;

/**
 * What a render produced.
 *
 * @param image       the picture
 * @param plan        the effects simulated
 * @param rays        rays cast, by kind
 * @param renderNanos wall-clock time of the tracing
 * @param threads     threads used
 * @param pixelRays   per kind, rays cast on behalf of each pixel (row-major), or null when not recorded
 * @param stopped     whether the render was stopped before every tile was done
 * @param tracer      how the rays were traced: which tracer, through which loop of the structure
 */
public record RenderResult(Image image, EffectPlan plan, RayCounts rays, long renderNanos, int threads,
                           int[][] pixelRays, boolean stopped, String tracer) {

    /**
     * {@return rays of {@code kind} cast for pixel (x, y)}; needs a render that recorded them.
     *
     * @param kind the kind
     * @param x the pixel's column
     * @param y the pixel's row
     * @throws IllegalStateException if per-pixel rays were not recorded
     */
    public int pixelRays(RayKind kind, int x, int y) {
        if (pixelRays == null) throw new IllegalStateException("per-pixel rays were not recorded");
        return pixelRays[kind.ordinal()][y * image.width() + x];
    }
}
