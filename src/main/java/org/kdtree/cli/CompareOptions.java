package org.kdtree.cli;

import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.Supervisor;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.PointsKd;
import org.kdtree.spec.BuilderSpec;
import picocli.CommandLine.Mixin;

/**
 * The options of the commands that compare trees ({@code compare-trees}, {@code similar}; a
 * picocli mixin of mixins): the builder of every tree compared (a kd-tree builder, by default the
 * one for the data's kind), how long a plug-in builder may take, and {@code --quiet}, taken as every
 * command takes it (these draw no bar: they print a few lines); with the one way they build.
 */
final class CompareOptions {
    /** The builder of point sets' trees when none is given: the one for points. */
    static final String POINTS_BUILDER = "sliding-midpoint";
    /** The builder of 2-D scenes' and meshes' trees when none is given. */
    static final String SCENE_BUILDER = "sah";

    @Mixin
    BuilderOptions options;

    @Mixin
    ProgressOption progress;

    @Mixin
    DeadlineOptions deadlines;

    /** @param trees which trees the builder builds, for the help (e.g. "both trees") */
    CompareOptions(String trees) {
        options = BuilderOptions.kdTrees(null, "the builder of " + trees + " (default: " + POINTS_BUILDER + " for points, "
                + SCENE_BUILDER + " for scenes and meshes)");
    }

    /**
     * {@return the builder of every tree of one comparison}: the one the options name, or else the
     * default for the kind of {@code first}; its settings and the deadlines checked now
     *
     * @param first the first data set read (the query, or A)
     */
    TreeMaker maker(Primitives first) {
        BuilderSpec spec = options.builder() != null ? options.spec() : options.spec(first instanceof PointsKd ? POINTS_BUILDER : SCENE_BUILDER);
        return new TreeMaker(spec, deadlines.supervisor());
    }

    /**
     * The builder of a comparison's trees, a plug-in's under the supervisor (the library's builders are trusted).
     *
     * @param spec       the builder and its settings
     * @param supervisor watches a plug-in's builds
     */
    record TreeMaker(BuilderSpec spec, Supervisor supervisor) {
        /** {@return the builder and its settings, in words}, as the commands print them and the cache keys its signatures */
        String describe() {
            return spec.builder() + " (" + spec.describe() + ")";
        }

        /**
         * {@return the tree the builder makes over {@code data}}
         *
         * @param data the data
         */
        KdTree build(Primitives data) {
            return supervisor.build(spec.create(), data);
        }
    }
}
