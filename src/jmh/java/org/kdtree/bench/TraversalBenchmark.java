package org.kdtree.bench;

import java.util.concurrent.TimeUnit;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.measure.RayBatch;
import org.kdtree.measure.RaySet;
import org.kdtree.shape.TriangleMesh;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;

/**
 * Traversal throughput for the spec's ray sets: P (1024 x 1024 primary rays) and R (1,000,000
 * random rays), closest hit, one thread, through a kd-tree or the bounding volume hierarchy
 * ({@code bvh}, with its fastest query). One operation traces the whole set, so
 * Mrays/s = 1.048576 (P) or 1.0 (R) / (ms per op / 1000). The scene is a procedural surface by
 * default; pass {@code -p mesh=/path/to/stanford-bunny.obj} (or {@code PATH@grid4}) for a real one.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 2)
@Measurement(iterations = 5)
// The module lets a JDK 21+ fork take the vector path (org.kdtree.accel.Vectorization); Java 17 stays scalar.
@Fork(value = 1, jvmArgsAppend = {"-Xmx6g", "--add-modules=jdk.incubator.vector"})
public class TraversalBenchmark {
    @Param({"surface"})
    public String mesh;

    @Param({"69451"})
    public int n;

    @Param({"P", "R"})
    public String rays;

    @Param({"sah-event", "sah-binned", "median-plane", "object-median", "bvh"})
    public String builder;

    private RayBatch batch;
    private RaySet set;

    @Setup(Level.Trial)
    public void setUp() {
        TriangleMesh m = BenchScenes.make(mesh, n);
        batch = new RayBatch(1, BuildBenchmark.structure(builder, m));
        set = rays.equals("P") ? RaySet.primary(m, RaySet.SPEC_IMAGE) : RaySet.random(m, RaySet.SPEC_RANDOM_RAYS);
    }

    @TearDown(Level.Trial)
    public void tearDown() {
        batch.close();
    }

    @Benchmark
    public RayBatch.Checksum trace() {
        return batch.trace(set);
    }
}
