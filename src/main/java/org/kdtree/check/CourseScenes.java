package org.kdtree.check;

import java.util.List;
import org.kdtree.generate.Meshes;
import org.kdtree.generate.Shapes;
import org.kdtree.io.BundledScenes;
import org.kdtree.shape.Primitives;

/**
 * The scenes a builder is graded on: the bundled scenes a course uses (the talk's figures, the
 * Cornell box, the clustered spheres; not the sphereflake's million triangles, which would make
 * grading slow) and two of the contract's generated ones ({@link Shapes#mixed mixed 2-D shapes},
 * {@link Meshes#cornerClusters corner clusters}), each with the name a report shows.
 */
public final class CourseScenes {
    /**
     * A named scene.
     * @param name as a report shows it
     * @param primitives the scene's primitives
     */
    public record Named(String name, Primitives primitives) {
    }

    private CourseScenes() {
    }

    /**
     * {@return the course scenes} Made once per JVM: primitives are read-only, and a class's
     * grades replay them for every student.
     */
    public static List<Named> all() {
        return Made.ALL;
    }

    /** Made on first use. */
    private static final class Made {
        static final List<Named> ALL = List.of(
                bundled("talk-figures.scene2d"),
                new Named("mixed 2-D shapes", Shapes.named("mixed", 400)),
                new Named("corner clusters", Meshes.cornerClusters(600, 4)),
                bundled("cornell-box.json"),
                bundled("clustered-spheres.obj"));
    }

    private static Named bundled(String file) {
        return new Named(file.substring(0, file.lastIndexOf('.')), BundledScenes.load(file));
    }
}
