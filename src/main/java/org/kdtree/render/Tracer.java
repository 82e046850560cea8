package org.kdtree.render;

import org.kdtree.accel.PacketQuery;
import org.kdtree.accel.RayQuery;
import org.kdtree.scene.Scene;

/**
 * One thread's ray tracer: the recursive tracer ({@link WhittedTracer}) one pixel at a time, and,
 * when given a packet query that traces a packet's rays together and repays it in renders ({@link
 * PacketQuery#repaysBlocks}: neither structure's does today) or when asked for, the block tracer
 * ({@link BlockTracer}) 8 x 8 pixels at a time, their rays in packets. Both follow the records of
 * one {@link Shader}, so a pixel's colour and rays are the same, bit for bit, whichever traces it.
 * Tracing allocates nothing.
 */
final class Tracer {
    /**
     * The most light samples a block keeps aside at once (nodes of its ray trees times shadow
     * slots per node: about 90 bytes each): past {@code shadowBudget / slots} nodes, a tree's
     * further reflection and refraction rays are traced depth first where they arise, so that
     * deep trees of glass and mirrors under many light samples stay within a few megabytes.
     */
    static final int SHADOW_BUDGET = 1 << 16;
    /** The most light samples per shaded point the block tracer keeps (more: pixels are traced one at a time). */
    private static final int MAX_SLOTS = 1024;

    private final RayCounts counts = new RayCounts();
    private final WhittedTracer pixels;
    /**
     * The block tracer, when given packets traced together and lights of at most {@link
     * #MAX_SLOTS} samples per point; else null.
     */
    private final BlockTracer blocks;
    /** How it traces, for the render's report. */
    private final String describe;

    /**
     * A tracer for one thread, one pixel at a time.
     *
     * @param scene the scene
     * @param plan  which rays to cast
     * @param query this thread's ray queries against the structure
     */
    Tracer(Scene scene, EffectPlan plan, RayQuery query) {
        this(scene, plan, query, null, SHADOW_BUDGET, false);
    }

    /**
     * A tracer for one thread, in blocks of pixels when {@code packets} traces a packet's rays
     * together and repays it or {@code asked} (else one pixel at a time).
     *
     * @param scene        the scene
     * @param plan         which rays to cast
     * @param query        this thread's ray queries against the structure
     * @param packets      this thread's packet queries against it, or null
     * @param shadowBudget the block's budget of light samples kept aside ({@link #SHADOW_BUDGET}; tests make it small)
     * @param asked        whether blocks are asked for even where the packet loop does not repay them
     */
    Tracer(Scene scene, EffectPlan plan, RayQuery query, PacketQuery packets, int shadowBudget, boolean asked) {
        Shader shader = new Shader(scene, plan);
        pixels = new WhittedTracer(scene, shader, plan.maxDepth(), query, counts);
        boolean together = packets != null && packets.tracesTogether(), fits = shader.slots() <= MAX_SLOTS;
        boolean repaid = together && packets.repaysBlocks();
        blocks = (repaid || together && asked) && fits ? new BlockTracer(scene, shader, packets, pixels, counts, shadowBudget) : null;
        describe = blocks != null ? "blocks of 8 x 8 pixels, breadth first, their rays in packets through the packet loop"
                + (repaid ? "" : " (asked for; slower in renders than single rays)")
                : "the recursive tracer, one pixel at a time, each ray through the single-ray loop" + (packets == null ? ""
                : !together ? " (the structure's packets would trace each ray alone)"
                : !(repaid || asked) ? " (the structure's packet loop is slower in renders than its single rays)"
                : " (more than " + MAX_SLOTS + " light samples per point for the block tracer)");
    }

    /** {@return how it traces, in a few words: which tracer, and which loop} */
    String describe() { return describe; }

    /** {@return the rays this tracer has cast so far} */
    RayCounts counts() { return counts; }

    /**
     * Writes the mean radiance of pixel (x, y) over the scene's samples per pixel to {@code rgb}.
     *
     * @param x   the pixel's column
     * @param y   the pixel's row
     * @param rgb receives the linear red, green and blue radiance
     */
    void pixel(int x, int y, double[] rgb) { pixels.pixel(x, y, rgb); }

    /** {@return whether this tracer renders blocks of pixels with their rays in packets ({@link #block})}: the image is the same either way. */
    boolean tracesPackets() { return blocks != null; }

    /**
     * Traces the pixels {@code [x0, x1) x [y0, y1)} (at most {@link BlockTracer#SIZE}) together,
     * their rays in packets. Only when {@link #tracesPackets}.
     *
     * @param x0 the block's first column
     * @param y0 its first row
     * @param x1 one past its last column
     * @param y1 one past its last row
     */
    void block(int x0, int y0, int x1, int y1) { blocks.block(x0, y0, x1, y1); }

    /**
     * Writes the colour of pixel {@code i} of the last {@link #block} to {@code rgb}, as {@link #pixel} would.
     *
     * @param i   the pixel's index in the block (row by row)
     * @param rgb receives the linear red, green and blue radiance
     */
    void blockColour(int i, double[] rgb) { blocks.colour(i, rgb); }

    /**
     * {@return the rays of {@code kind} the last {@link #block} cast for its pixel {@code i}}
     *
     * @param kind a kind of ray
     * @param i    the pixel's index in the block
     */
    int blockRays(RayKind kind, int i) { return blocks.rays(kind, i); }
}
