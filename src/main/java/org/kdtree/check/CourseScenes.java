package org.kdtree.check;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.List;
import org.kdtree.io.BundledScenes;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.shape.Primitives;

/**
 * The scenes a builder is graded on: the bundled scenes a course uses (the talk's figures, the
 * Cornell box, the clustered spheres; not the sphereflake's million
 * triangles, which would make grading slow) and two of the contract's generated ones
 * (random 2-D shapes, clustered triangles), each with the name a report shows.
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

    /** {@return the course scenes, read once per call} */
    public static List<Named> all() {
        return List.of(
                bundled("talk-figures.scene2d"),
                new Named("random 2-D shapes", ContractScenes.random2D(400, 1)),
                new Named("clustered triangles", ContractScenes.clusteredTriangles(600, 4)),
                bundled("cornell-box.json"),
                bundled("clustered-spheres.obj"));
    }

    private static Named bundled(String file) {
        try {
            return new Named(file.substring(0, file.lastIndexOf('.')), PrimitivesReader.read(BundledScenes.path(file)));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
