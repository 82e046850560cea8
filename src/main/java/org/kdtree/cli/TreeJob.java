package org.kdtree.cli;

import java.util.function.Supplier;
import org.kdtree.kdtree.Supervisor;
import org.kdtree.shape.Primitives;
import org.kdtree.spec.BuilderSpec;
import picocli.CommandLine.Mixin;

/**
 * The options of the commands that make one tree over a scene and then work on it ({@code stats},
 * {@code raycast}, {@code render}; a picocli mixin of mixins): where the tree comes from or goes
 * ({@link TreeOptions}), whether progress is shown ({@link ProgressOption}) and how long a plug-in
 * builder may take ({@link DeadlineOptions}), with the one way these commands obtain their tree.
 */
final class TreeJob {
    @Mixin
    TreeOptions trees = new TreeOptions();

    @Mixin
    ProgressOption progress;

    @Mixin
    DeadlineOptions deadlines;

    /**
     * The tree over {@code primitives}: loaded from {@code --tree}, or built by {@code spec} under
     * the deadlines given (checked now, before any work), as {@link TreeOptions#obtaining} gives it,
     * to run (and time) later.
     *
     * @param options    the builder options given, which a loaded tree must not contradict
     * @param spec       the builder and settings those options name
     * @param primitives the scene's primitives
     * @return the supplier of the structure and the spec it was built with
     */
    Supplier<TreeOptions.Obtained> obtaining(BuilderOptions options, BuilderSpec spec, Primitives primitives) {
        Supervisor supervisor = deadlines.supervisor();
        return trees.obtaining(options, primitives, () -> spec.build(primitives, supervisor));
    }
}
