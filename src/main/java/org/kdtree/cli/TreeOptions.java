package org.kdtree.cli;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.Map;
import java.util.Objects;
import java.util.function.Supplier;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.Setting;
import org.kdtree.accel.SharedSettings;
import org.kdtree.shape.Primitives;
import org.kdtree.spec.BuilderSpec;
import org.kdtree.treefile.SavedTree;
import org.kdtree.treefile.TreeFile;
import picocli.CommandLine.Option;

/**
 * {@code --save-tree FILE} and {@code --tree FILE} of the commands that build a tree (a picocli
 * mixin): save the tree a command built, or load one saved earlier instead of building it
 * (docs/tree-files.md). A loaded tree is the file's: its builder and settings are said with it,
 * and builder options that ask for another are refused rather than ignored ({@code --threads},
 * which never changes a tree, excepted).
 */
final class TreeOptions {
    @Option(names = "--save-tree", paramLabel = "FILE",
            description = "Save the tree built to FILE (written whole or not at all), to load it later with --tree.")
    Path saveTree;

    @Option(names = "--tree", paramLabel = "FILE",
            description = "Load the tree saved in FILE (by --save-tree, over the same scene) instead of building one.")
    Path tree;

    /** {@return whether a tree is loaded rather than built} */
    boolean loads() { return tree != null; }

    /**
     * Refuses, before any work, what cannot be: both options, a {@code --save-tree} file that is
     * one of the command's other files (by any spelling or link), an output that cannot be written.
     *
     * @param namesAndFiles the command's other files, each after its name as its help gives it
     *                      ("SCENE", scene, "-o", output, ...); a null file is left out
     */
    void check(Object... namesAndFiles) {
        if (saveTree != null && tree != null)
            throw new IllegalArgumentException("--tree " + tree + " loads a tree, --save-tree " + saveTree + " saves the one built: give one of them");
        if (saveTree == null) return;
        for (int i = 0; i + 1 < namesAndFiles.length; i += 2) {
            Path other = (Path) namesAndFiles[i + 1];
            if (other != null && !other.toString().equals("-") && SameFile.same(saveTree, other))
                throw new IllegalArgumentException("--save-tree " + saveTree + " is " + namesAndFiles[i] + " (" + other
                        + "); save the tree elsewhere");
        }
        CommandFiles.requireWritable("--save-tree", saveTree);
    }

    /**
     * The structure, loaded from {@code --tree} (over {@code primitives}, checked to be those it was
     * built over) or built by {@code build}.
     *
     * @param options    the builder options given, which a loaded tree must not contradict
     * @param primitives the scene's primitives
     * @param build      builds the structure the options name
     * @return the structure and the builder spec it was built with
     * @throws IOException naming the tree file and what is wrong with it, in one line
     */
    Obtained obtain(BuilderOptions options, Primitives primitives, Supplier<AccelerationStructure> build) throws IOException {
        if (tree == null) return new Obtained(build.get(), options.spec());
        SavedTree saved = TreeFile.load(tree, primitives);
        requireSame(options, saved.spec());
        return new Obtained(saved.structure(), saved.spec());
    }

    /** A structure as {@link #obtain} gives it: built or loaded, with the spec it was built with. */
    record Obtained(AccelerationStructure structure, BuilderSpec spec) {
    }

    /** As {@link #obtain}, unchecked, for a timed supplier: {@link #unwrap} gives the load's own error back. */
    Supplier<Obtained> obtaining(BuilderOptions options, Primitives primitives, Supplier<AccelerationStructure> build) {
        return () -> {
            try {
                return obtain(options, primitives, build);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        };
    }

    /**
     * Runs {@code timed}, giving back a load's {@link IOException} as itself (one line).
     *
     * @param timed what runs {@link #obtaining}'s supplier
     * @param <T>   its result
     * @return its result
     * @throws IOException the load's error
     */
    static <T> T unwrap(Supplier<T> timed) throws IOException {
        try {
            return timed.get();
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
    }

    /**
     * Saves {@code structure} to {@code --save-tree}, if given.
     *
     * @param structure  what the command built
     * @param spec       what it was built with
     * @param primitives what it was built over
     * @throws IOException if the file cannot be written
     */
    void save(AccelerationStructure structure, BuilderSpec spec, Primitives primitives) throws IOException {
        if (saveTree != null) TreeFile.save(saveTree, structure, spec, primitives);
    }

    /** Refuses builder options that ask for another builder or setting than the loaded tree's ({@code --threads} excepted). */
    private void requireSame(BuilderOptions options, BuilderSpec saved) {
        boolean same = !options.builderGiven() || options.builder().equals(saved.builder());
        for (Map.Entry<Setting<?>, Object> e : options.givenSettings().entrySet())
            if (e.getKey() != SharedSettings.THREADS && !Objects.equals(e.getValue(), saved.value(e.getKey()))) same = false;
        if (!same)
            throw new IllegalArgumentException("--tree " + tree + " holds a tree built by " + saved + "; the builder options ask for another: "
                    + "leave them out to use the file's tree, or build anew without --tree");
    }
}
