package org.kdtree.bench;

import java.util.concurrent.TimeUnit;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.KdTreeBuilder;
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
import org.openjdk.jmh.annotations.Warmup;

/**
 * The O(N^2) SAH (and, for the same N, the sorted and event algorithms, to draw the three
 * curves on one chart) up to the N where the naive build takes a few seconds.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 1)
@Measurement(iterations = 3)
@Fork(value = 1, jvmArgsAppend = {"-Xmx4g"})
public class NaiveBuildBenchmark {
    @Param({"uniform", "clustered", "surface"})
    public String scene;

    @Param({"1000", "2000", "4000", "8000", "16000"})
    public int n;

    @Param({"sah-naive", "sah-sorted", "sah-event"})
    public String builder;

    private TriangleMesh mesh;
    private KdTreeBuilder kd;

    @Setup(Level.Trial)
    public void setUp() {
        mesh = BenchScenes.make(scene, n);
        kd = BuildBenchmark.builder(builder);
    }

    @Benchmark
    public KdTree build() {
        return kd.build(mesh);
    }
}
