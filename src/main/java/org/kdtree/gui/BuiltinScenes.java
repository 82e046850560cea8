package org.kdtree.gui;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.IntFunction;
import java.util.function.Supplier;
import org.kdtree.generate.Shapes;
import org.kdtree.io.BundledScenes;
import org.kdtree.shape.Shape2D;

/**
 * The workbench's Scene menu and generator box. The named scenes are the bundled {@code .scene2d}
 * files ({@link BundledScenes}), so that a name means the same shapes, and the same cost, in the
 * workbench, the command line and the contract; the generators draw {@link Shapes#named the scenes of a
 * name and a count}, so the same count gives the same scene, the one the benchmark, the contract
 * and the tests use by that name (the bundled uniform, clustered and overlapping scenes are
 * theirs at 200, 200 and 60).
 */
final class BuiltinScenes {
    private BuiltinScenes() {
    }

    /** {@return the built-in scenes by name, in menu order}; the first is the one the workbench opens on. */
    static Map<String, Supplier<List<Shape2D>>> all() {
        Map<String, Supplier<List<Shape2D>>> m = new LinkedHashMap<>();
        m.put("Talk figures", BuiltinScenes::talkFigures);
        m.put("Uniform (200)", () -> bundled("uniform-200.scene2d"));
        m.put("Clustered (200)", () -> bundled("clustered-200.scene2d"));
        m.put("Long thin object", () -> bundled("long-thin.scene2d"));
        m.put("Many overlapping (60)", () -> bundled("overlapping-60.scene2d"));
        return m;
    }

    /** {@return the random generators by name, each taking a count} */
    static Map<String, IntFunction<List<Shape2D>>> generators() {
        Map<String, IntFunction<List<Shape2D>>> m = new LinkedHashMap<>();
        m.put("Uniform", n -> Shapes.named("uniform", n).shapes());
        m.put("Clustered", n -> Shapes.named("clustered", n).shapes());
        m.put("Overlapping", n -> Shapes.named("overlapping", n).shapes());
        m.put("Mixed shapes", n -> Shapes.named("mixed", n).shapes());
        return m;
    }

    /** {@return the talk's figures 2-5, the bundled scenes/talk-figures.scene2d}: two small objects at the left, a long thin one, a cluster at the right. */
    static List<Shape2D> talkFigures() {
        return bundled("talk-figures.scene2d");
    }

    private static List<Shape2D> bundled(String file) {
        return BundledScenes.read2D(file).shapes();
    }
}
