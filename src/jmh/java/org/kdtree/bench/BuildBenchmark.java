package org.kdtree.bench;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.SharedSettings;
import org.kdtree.accel.StructureBuilder;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.kdtree.Quality;
import org.kdtree.kdtree.SahBuilder;
import org.kdtree.kdtree.SahSettings;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.spec.BuilderSpec;
import org.kdtree.spec.Builders;
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
 * Construction time of every builder and SAH algorithm, and of the bounding volume hierarchy
 * ({@code bvh}, also {@code bvh-width2} and {@code bvh-width8}), over N = 1K .. 1M on three kinds of
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

    @Param({"sah-event", "sah-sorted", "sah-binned", "median-plane", "object-median", "bvh"})
    public String builder;

    @Param({"1"})
    public int threads;

    private TriangleMesh mesh;
    /** One whole build with a builder made up front: a kd-tree builder's or the BVH's. */
    private Function<TriangleMesh, Object> build;

    @Setup(Level.Trial)
    public void setUp() {
        mesh = BenchScenes.make(scene, n);
        BuilderSpec s = spec(builder).with(SharedSettings.THREADS, threads);
        StructureBuilder b = s.structureBuilder();
        build = b::build;
    }

    @Benchmark
    public Object build() {
        return build.apply(mesh);
    }

    /** The builders the benchmarks measure, by their parameter name: each a {@link BuilderSpec}. */
    static final Map<String, BuilderSpec> SPECS = specs();

    private static Map<String, BuilderSpec> specs() {
        BuilderSpec sah = BuilderSpec.of("sah");
        Map<String, BuilderSpec> m = new LinkedHashMap<>();
        m.put("sah-naive", sah.with(SahSettings.ALGORITHM, SahBuilder.Algorithm.NAIVE));
        m.put("sah-sorted", sah.with(SahSettings.ALGORITHM, SahBuilder.Algorithm.SORTED));
        m.put("sah-event", sah.with(SahSettings.ALGORITHM, SahBuilder.Algorithm.EVENT));
        m.put("sah-binned", sah.with(SahSettings.ALGORITHM, SahBuilder.Algorithm.BINNED));
        m.put("sah-balanced", sah.with(SahSettings.QUALITY, Quality.BALANCED));
        m.put("sah-fast", sah.with(SahSettings.QUALITY, Quality.FAST));
        for (String name : Builders.names()) m.putIfAbsent(name, BuilderSpec.of(name));
        m.put(BvhBuilder.NAME, BuilderSpec.of(BvhBuilder.NAME));
        m.put("bvh-width2", BuilderSpec.of(BvhBuilder.NAME).with(BvhBuilder.WIDTH, 2));
        m.put("bvh-width8", BuilderSpec.of(BvhBuilder.NAME).with(BvhBuilder.WIDTH, 8));
        return m;
    }

    /** The spec of the benchmark parameter {@code name}: one of {@link #SPECS}, or any registered builder's name. */
    static BuilderSpec spec(String name) {
        BuilderSpec spec = SPECS.get(name);
        if (spec == null) throw new IllegalArgumentException("unknown builder " + name + "; known: " + SPECS.keySet());
        return spec;
    }

    /** A new kd-tree builder of the benchmark parameter {@code name} ({@link #spec}); "bvh" is refused in one line. */
    static KdTreeBuilder builder(String name) {
        return spec(name).create();
    }

    /** The structure the benchmark parameter {@code name} builds over {@code mesh}: a kd-tree or a BVH ({@link #spec}). */
    static AccelerationStructure structure(String name, TriangleMesh mesh) {
        return spec(name).build(mesh, null);
    }
}
