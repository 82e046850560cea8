package org.kdtree.render;

import java.util.Locale;
import java.util.function.Supplier;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.kdtree.Supervisor;
import org.kdtree.scene.Camera;
import org.kdtree.scene.Scene;
import org.kdtree.spec.BuilderSpec;

/**
 * A whole render: build the acceleration structure over the scene's mesh (a kd-tree with the
 * given builder, or what a {@link BuilderSpec} names: a kd-tree or a bounding volume hierarchy),
 * then trace it with one query per thread over a shared {@link TriangleIntersector}.
 *
 * @param scene       the scene rendered
 * @param structure   the structure built
 * @param builderName the name of the builder that built it
 * @param buildNanos  wall-clock build time
 * @param result      the image, the plan and the rays cast
 */
public record RenderJob(Scene scene, AccelerationStructure structure, String builderName, long buildNanos, RenderResult result) {

    /**
     * Builds the tree and renders.
     *
     * @param scene the scene
     * @param builder builds the tree over the scene's triangles
     * @param options threads, tiles and progress
     * @return the finished job
     */
    public static RenderJob run(Scene scene, KdTreeBuilder builder, Renderer.Options options) {
        return run(scene, builder, null, options);
    }

    /**
     * Builds the tree under {@code supervisor} (a plug-in builder's: it may throw, hang or be
     * slow, and is stopped and named if so), then renders.
     *
     * @param scene the scene
     * @param builder builds the tree over the scene's triangles
     * @param supervisor runs the build; null to build on this thread, unsupervised
     * @param options threads, tiles and progress
     * @return the finished job
     * @throws org.kdtree.kdtree.BuilderFault if the builder failed under supervision
     */
    public static RenderJob run(Scene scene, KdTreeBuilder builder, Supervisor supervisor, Renderer.Options options) {
        return run(scene, builder.name(), () ->
                supervisor == null ? builder.build(scene.mesh()) : supervisor.build(builder, scene.mesh()), options);
    }

    /**
     * Builds the structure {@code spec} names (a kd-tree under {@code supervisor}, or a bounding
     * volume hierarchy), then renders: the same image whichever it is.
     *
     * @param scene the scene
     * @param spec the builder and its settings
     * @param supervisor runs a kd-tree builder; null to build on this thread, unsupervised
     * @param options threads, tiles and progress
     * @return the finished job
     * @throws IllegalArgumentException if the spec names no builder or a setting its builder does not take
     * @throws org.kdtree.kdtree.BuilderFault if a kd-tree builder failed under supervision
     */
    public static RenderJob run(Scene scene, BuilderSpec spec, Supervisor supervisor, Renderer.Options options) {
        return run(scene, spec.builder(), () -> spec.build(scene.mesh(), supervisor), options);
    }

    /**
     * Makes the structure with {@code build} (a build, or a load of a saved tree), timed, then renders.
     *
     * @param scene the scene
     * @param builderName who made the structure, as the summary says it
     * @param build makes the structure over the scene's triangles
     * @param options threads, tiles and progress
     * @return the finished job
     */
    public static RenderJob run(Scene scene, String builderName, Supplier<AccelerationStructure> build, Renderer.Options options) {
        long t0 = System.nanoTime();
        AccelerationStructure structure = build.get();
        long buildNanos = System.nanoTime() - t0;
        RenderResult result = Renderer.render(scene, structure, options);
        return new RenderJob(scene, structure, builderName, buildNanos, result);
    }

    /**
     * {@return a count with its noun}, in the plural where it is not one: "1 light", "2 lights".
     *
     * @param n the count
     * @param noun the noun in the singular
     */
    public static String count(long n, String noun) {
        return String.format(Locale.ROOT, "%,d %s%s", n, noun, n == 1 ? "" : "s");
    }

    /**
     * {@return the summary printed after a render}: scene, plan, times, rays by kind and per second, the structure's statistics.
     */
    public String summary() {
        StringBuilder s = new StringBuilder();
        Camera c = scene.camera();
        s.append(String.format(Locale.ROOT, "scene: %s (%s, %s, %s)%n", scene.name(), count(scene.mesh().size(), "triangle"),
                count(scene.materials().size(), "material"), count(scene.lights().size(), "light")));
        s.append(String.format(Locale.ROOT, "image: %d x %d, %s per pixel, %s%n", c.width(), c.height(),
                count(scene.samplesPerPixel(), "sample"), count(result.threads(), "thread")));
        s.append(result.plan().describe()).append(System.lineSeparator());
        s.append(String.format(Locale.ROOT, "build time: %.1f ms (%s)%n", buildNanos / 1e6, builderName));
        s.append(String.format(Locale.ROOT, "render time: %.1f ms%s%n", result.renderNanos() / 1e6,
                result.stopped() ? " (stopped before the last tile)" : ""));
        s.append(rayLines(result.rays(), result.renderNanos()));
        // which engine made the figures above: the same words as render's and raycast's notes on standard error
        s.append(String.format(Locale.ROOT, "traced by: %s, %s; path: %s%n", structure.kind(), result.tracer(), structure.describePath()));
        s.append(structure.kind()).append(':').append(System.lineSeparator());
        for (String line : structure.stats().describe().split("\\R")) s.append("  ").append(line).append(System.lineSeparator());
        return s.toString();
    }

    /**
     * {@return the "rays:" lines of a render's report: the count of each kind, and one rate for
     * them all}. The kinds are traced interleaved, not timed apart, so a rate per kind would only
     * divide its count by the whole render time.
     *
     * @param rays        the rays cast, by kind
     * @param renderNanos the render's wall-clock time
     */
    public static String rayLines(RayCounts rays, long renderNanos) {
        StringBuilder s = new StringBuilder("rays:").append(System.lineSeparator());
        for (RayKind k : RayKind.values()) s.append(String.format(Locale.ROOT, "  %-10s %,14d%n", k.label(), rays.get(k)));
        s.append(String.format(Locale.ROOT, "  %-10s %,14d  (%,.0f rays/s over the render time)%n", "total", rays.total(),
                rays.total() / (Math.max(1, renderNanos) / 1e9)));
        return s.toString();
    }
}
