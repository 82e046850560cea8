package org.kdtree.bench;

import java.util.concurrent.TimeUnit;
import org.kdtree.compare.TreeDistance;
import org.kdtree.compare.TreeSignature;
import org.kdtree.generate.Points;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.SlidingMidpointBuilder;
import org.kdtree.shape.PointsKd;
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
 * Issue 48's costs of comparing data by their kd-trees (docs/compare.md), on one thread, over
 * sets of 10,000 points (uniform, or the clustered set of the nearest-neighbour study):
 * {@link #compareThousand} is 1,000 signature comparisons (one query against 1,000 signatures,
 * as {@code similar} ranks a folder), which must take well under a second;
 * {@link #buildTree} and {@link #signatureOfTree} split the making of a signature into the tree's
 * build and the signature's own walk over the built tree, which must cost less than the build.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
public class CompareBenchmark {
    static final int N = 10_000, SIGNATURES = 1000, SETS = 20;

    @Param({"2", "5"})
    public int dimension;

    @Param({"uniform", "clustered"})
    public String data;

    private PointsKd points;
    private KdTree tree;
    private TreeSignature query;
    private TreeSignature[] signatures;

    @Setup(Level.Trial)
    public void setUp() {
        points = Points.named(data, N, dimension, 1);
        tree = new SlidingMidpointBuilder().build(points);
        query = TreeSignature.of(tree);
        TreeSignature[] distinct = new TreeSignature[SETS];   // 20 different sets, each signature 50 times: the arrays stay in memory as a folder's would
        for (int i = 0; i < SETS; i++) distinct[i] = TreeSignature.of(new SlidingMidpointBuilder().build(Points.named(i % 2 == 0 ? "uniform" : "clustered", N, dimension, 100 + i)));
        signatures = new TreeSignature[SIGNATURES];
        for (int i = 0; i < SIGNATURES; i++) signatures[i] = TreeSignature.fromBytes(distinct[i % SETS].toBytes());
    }

    /** {@return the sum of 1,000 distances} (one query's ranking of a folder of 1,000 signatures) */
    @Benchmark
    public double compareThousand() {
        double sum = 0;
        for (TreeSignature s : signatures) sum += TreeDistance.of(query, s);
        return sum;
    }

    /** {@return the sliding-midpoint tree over the 10,000 points} */
    @Benchmark
    public KdTree buildTree() {
        return new SlidingMidpointBuilder().build(points);
    }

    /** {@return the signature of the built tree} (the cost a signature adds to the tree's build) */
    @Benchmark
    public TreeSignature signatureOfTree() {
        return TreeSignature.of(tree);
    }
}
