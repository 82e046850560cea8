package org.kdtree.gui;

import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.concurrent.TimeUnit;
import org.kdtree.generate.Shapes;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.Scene2D;
import org.kdtree.spec.BuilderSpec;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Interactive speed of the workbench: what one edit costs on a 10,000-object 2-D scene with the
 * SAH (rebuild the tree, then repaint the canvas into a 1000 x 800 image, as Swing would), on the
 * scene the workbench's generator makes for that count.
 * Target: under 50 ms. {@code mvn -B -Pbench package -DskipTests && java -jar target/benchmarks.jar WorkbenchBenchmark}.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 5, time = 1)
@Measurement(iterations = 10, time = 1)
@Fork(value = 1, jvmArgsAppend = "-Djava.awt.headless=true")
public class WorkbenchBenchmark {
    @Param({"uniform", "clustered"})
    public String scene;

    @Param({"10000"})
    public int objects;

    private Scene2D shapes;
    private BufferedImage image;

    @Setup public void setUp() {
        shapes = Shapes.named(scene, objects);   // the workbench's Generate
        image = new BufferedImage(1000, 800, BufferedImage.TYPE_INT_RGB);
    }

    @Benchmark public KdTree rebuild() {
        return BuilderSpec.of("sah").create().build(shapes);
    }

    @Benchmark public BufferedImage rebuildAndRepaint() {
        KdTree tree = BuilderSpec.of("sah").create().build(shapes);
        Graphics2D g = image.createGraphics();
        ViewTransform v = new ViewTransform().fit(tree.bounds(), image.getWidth(), image.getHeight());
        TreePainter.paint(g, image.getWidth(), image.getHeight(), shapes, tree, v, TreePainter.Options.PLAIN);
        g.dispose();
        return image;
    }
}
