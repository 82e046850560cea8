package org.kdtree.limits;

import java.util.List;

/**
 * Every setting's allowed range, in one list: the API, the command line, the scene files and
 * the workbench all check against these, so a value allowed in one place is allowed in all.
 * docs/limits.md shows the same table (a test keeps the two in step).
 */
public final class Limits {
    // Building a tree.
    /** Threads building a tree, tracing a ray set or rendering an image. */
    public static final Limit THREADS = Limit.whole("threads", 1, 256);
    /** Kmaxdepth, the depth cap of a tree; -1 lets the builder choose from the primitive count. */
    public static final Limit MAX_DEPTH = Limit.whole("Kmaxdepth", -1, 64).noting("-1 = auto: 8 + 1.3 log2 N for a kd-tree, 64 for a BVH");
    /** The factor c of an automatic depth cap 8 + c log2 N. */
    public static final Limit DEPTH_FACTOR = Limit.real("depth factor c", 0, 4);
    /** References the tree may hold per input primitive before nodes become leaves early. */
    public static final Limit REFERENCE_BUDGET = Limit.whole("reference budget", 1, 1 << 16);
    /** Kt, the SAH's cost of one traversal step. */
    public static final Limit KT = Limit.real("Kt", 0, 10_000);
    /** Ki, the SAH's cost of one primitive test. */
    public static final Limit KI = Limit.real("Ki", 0.001, 10_000);
    /** lambda, the SAH's weight of a plane that leaves one side empty. */
    public static final Limit LAMBDA = Limit.real("lambda", 0.01, 1);
    /** Kmintri, the median builders' smallest node worth splitting. */
    public static final Limit MIN_PRIMITIVES = Limit.whole("Kmintri", 0, 1_000_000);
    /** Bins per axis of the binned SAH. */
    public static final Limit BINS = Limit.whole("bins", 2, 1_000_000);
    /** Reference count below which the binned SAH switches to the exact sweep. */
    public static final Limit EXACT_BELOW = Limit.whole("exact below", 0, 1_000_000_000).noting("0 = never");
    /** The largest leaf of the sliding-midpoint builder and of a bounding volume hierarchy. */
    public static final Limit LEAF_SIZE = Limit.whole("leaf size", 1, 1 << 16);
    /** Children per node of a bounding volume hierarchy's collapsed (wide) layout. */
    public static final Limit BVH_WIDTH = Limit.whole("BVH width", 2, 8);
    /** The SAH's smallest node it searches a plane for: smaller ones become leaves. */
    public static final Limit LEAF_BELOW = Limit.whole("leaf below", 1, 1 << 16).noting("1 = only empty nodes");
    /**
     * Splits the SAH still makes on one path past the point where its cost criterion says stop
     * (each kept only where its subtree ends cheaper): pbrt-v3 allows 3; past a few, a build spends
     * more and more on subtrees that are mostly thrown away.
     */
    public static final Limit LOOKAHEAD = Limit.whole("lookahead", 0, 8).noting("0 = stop where the cost says so");
    /** How long one call of a supervised builder's terminate or findPlane may take before it is reported as hung ({@link Deadlines}). */
    public static final Limit CALL_DEADLINE = Limit.real("call deadline", 0.1, 3600).noting("seconds");
    /** How long one supervised build may take before it is reported as slow ({@link Deadlines}). */
    public static final Limit BUILD_DEADLINE = Limit.real("build deadline", 0.1, 86_400).noting("seconds");
    /** How long one student's whole grade, in a JVM of its own, may take before that JVM is killed ({@code grade-class}). */
    public static final Limit STUDENT_DEADLINE = Limit.real("student deadline", 1, 86_400).noting("seconds");
    /** The heap of one student's grading JVM ({@code grade-class}): a builder that allocates without bound stops there. */
    public static final Limit STUDENT_HEAP = Limit.whole("student heap", 64, 65_536).noting("MB");
    /**
     * {@code grade-class}'s default student deadline, in seconds: a grade takes a sound builder
     * seconds, and a hung one at most the contract's 10 s call deadline plus the quality builds'.
     */
    public static final double STUDENT_SECONDS = 300;
    /** {@code grade-class}'s default heap per student, in MB: the course scenes need far less. */
    public static final int STUDENT_HEAP_MB = 512;

    // Rendering.
    /** Image width and height, in pixels. */
    public static final Limit IMAGE_SIDE = Limit.whole("image side", 1, 16_384);
    /** Samples per pixel. */
    public static final Limit SAMPLES_PER_PIXEL = Limit.whole("samples per pixel", 1, 4096);
    /** Reflection and refraction depth. */
    public static final Limit RAY_DEPTH = Limit.whole("ray depth", 0, 64);
    /** Shadow-ray samples of one area light. */
    public static final Limit LIGHT_SAMPLES = Limit.whole("light samples", 1, 1024);

    /** Slices around a tessellated sphere (or each sphere of a sphereflake). */
    public static final Limit SPHERE_SEGMENTS = Limit.whole("sphere segments", 3, 4096);
    /** Stacks from pole to pole of a tessellated sphere. */
    public static final Limit SPHERE_RINGS = Limit.whole("sphere rings", 2, 4096);
    /** Recursion levels of a sphereflake ((9^(levels+1) - 1) / 8 spheres). */
    public static final Limit FLAKE_LEVELS = Limit.whole("sphereflake levels", 0, 6);

    // Measuring.
    /** Timed runs of a build or a ray set; the median is reported. */
    public static final Limit RUNS = Limit.whole("runs", 1, 1000);
    /** Untimed runs first, to warm up the JVM. */
    public static final Limit WARMUP = Limit.whole("warm-up runs", 0, 1000);
    /** N of the benchmark's N x N grid of copies of a mesh. */
    public static final Limit GRID = Limit.whole("grid", 1, 64);
    /** Rays in a generated ray set. */
    public static final Limit RAY_COUNT = Limit.whole("rays", 1, 100_000_000);
    /** Rays per triangle at which a trade-off chart adds trace time to build time. */
    public static final Limit RAYS_PER_TRIANGLE = Limit.real("rays per triangle", 0.001, 1_000_000);

    // Nearest neighbours of points.
    /** k, the neighbours asked of each query point (the answer has min(k, points) of them). */
    public static final Limit NEIGHBOURS = Limit.whole("neighbours k", 1, 100_000);
    /** Best-bin-first's budget: leaves a nearest-neighbour search scans before it stops. */
    public static final Limit LEAF_BUDGET = Limit.whole("leaf budget", 1, 1_000_000_000);
    /** eps of the (1 + eps) bound of an approximate nearest-neighbour search; 0 is exact. */
    public static final Limit EPSILON = Limit.real("epsilon", 0, 1000).noting("0 = exact");
    /** Data sets a similarity search prints, nearest first. */
    public static final Limit RANKED = Limit.whole("ranked data sets", 1, 100_000);
    /** Points of a generated point set. */
    public static final Limit POINT_COUNT = Limit.whole("points", 1, 50_000_000);
    /** Query points of a generated query set. */
    public static final Limit QUERY_COUNT = Limit.whole("queries", 1, 10_000_000);
    /** Dimensions of a tree (and so of a point set): {@code KdTree.MAX_DIMENSION} is this limit's maximum. */
    public static final Limit DIMENSION = Limit.whole("dimension", 1, 64);

    // Saved trees.
    /** A saved tree's file, in MB: what loading one may read and hold (one mapped buffer and Java's int arrays end at 2 GB). */
    public static final Limit TREE_FILE = Limit.whole("tree file", 1, 2047).noting("MB");

    // Scenes.
    /** Objects in a generated 2-D scene. */
    public static final Limit SCENE_OBJECTS = Limit.whole("objects", 1, 100_000);

    /** All of them, in the order of docs/limits.md (the workbench's own are in {@code gui.WorkbenchLimits}). */
    public static final List<Limit> ALL = List.of(THREADS, MAX_DEPTH, DEPTH_FACTOR, REFERENCE_BUDGET, KT, KI, LAMBDA,
            MIN_PRIMITIVES, BINS, EXACT_BELOW, LEAF_BELOW, LOOKAHEAD, LEAF_SIZE, BVH_WIDTH, CALL_DEADLINE, BUILD_DEADLINE, STUDENT_DEADLINE, STUDENT_HEAP, IMAGE_SIDE, SAMPLES_PER_PIXEL, RAY_DEPTH, LIGHT_SAMPLES,
            SPHERE_SEGMENTS, SPHERE_RINGS, FLAKE_LEVELS,
            RUNS, WARMUP, GRID, RAY_COUNT, RAYS_PER_TRIANGLE,
            NEIGHBOURS, LEAF_BUDGET, EPSILON, RANKED, POINT_COUNT, QUERY_COUNT, DIMENSION, TREE_FILE, SCENE_OBJECTS);

    private Limits() {
    }
}
