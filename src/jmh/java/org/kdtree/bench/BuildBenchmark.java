package org.kdtree.bench;

import java.util.concurrent.TimeUnit;
import org.kdtree.build.KdTreeBuilder;
import org.kdtree.build.MedianPlaneBuilder;
import org.kdtree.build.ObjectMedianBuilder;
import org.kdtree.build.Quality;
import org.kdtree.build.SahBuilder;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.tree.KdTree;
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
import org.openjdk.jmh.annotations.Warmup;

/**
 * Construction time of every builder and SAH algorithm over N = 1K .. 1M on three kinds of
 * scene. One operation = one whole build, single thread (set {@code -p threads=2} for the
 * parallel build). The naive O(N^2) SAH is in {@link NaiveBuildBenchmark}, with smaller N.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 2)
@Measurement(iterations = 5)
@Fork(value = 1, jvmArgsAppend = {"-Xmx6g"})
public class BuildBenchmark {
    @Param({"uniform", "clustered", "surface"})
    public String scene;

    @Param({"1000", "10000", "100000", "1000000"})
    public int n;

    @Param({"sah-event", "sah-sorted", "sah-binned", "median-plane", "object-median"})
    public String builder;

    @Param({"1"})
    public int threads;

    private TriangleMesh mesh;
    private KdTreeBuilder kd;

    @Setup(Level.Trial)
    public void setUp() {
        mesh = BenchScenes.make(scene, n);
        kd = builder(builder).threads(threads);
    }

    @Benchmark
    public KdTree build() {
        return kd.build(mesh);
    }

    static KdTreeBuilder builder(String name) {
        return switch (name) {
            case "sah-naive" -> new SahBuilder().algorithm(SahBuilder.Algorithm.NAIVE);
            case "sah-sorted" -> new SahBuilder().algorithm(SahBuilder.Algorithm.SORTED);
            case "sah-event" -> new SahBuilder().algorithm(SahBuilder.Algorithm.EVENT);
            case "sah-binned" -> new SahBuilder().algorithm(SahBuilder.Algorithm.BINNED);
            case "sah-balanced" -> new SahBuilder().quality(Quality.BALANCED);
            case "sah-fast" -> new SahBuilder().quality(Quality.FAST);
            case "median-plane" -> new MedianPlaneBuilder();
            case "object-median" -> new ObjectMedianBuilder();
            default -> throw new IllegalArgumentException("unknown builder " + name);
        };
    }
}
