package org.kdtree.check;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Random;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Supplier;
import org.kdtree.generate.HardMeshes;
import org.kdtree.generate.Meshes;
import org.kdtree.generate.Points;
import org.kdtree.generate.Shapes;
import org.kdtree.io.BundledScenes;
import org.kdtree.kdtree.BuilderFault;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.kdtree.Supervisor;
import org.kdtree.limits.Deadlines;
import org.kdtree.shape.InvalidGeometryException;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.shape.TriangleMesh;

/**
 * The contract every {@link KdTreeBuilder} must honour, as named cases: every primitive is
 * listed in every leaf whose voxel it overlaps and in no other; the leaves tile the root voxel;
 * every split plane lies inside its voxel; no leaf is deeper than the depth cap; the builder
 * stops on its own, before the cap; hard inputs (empty scene, one primitive, 10,000 identical
 * triangles, flat scenes, degenerate triangles, NaN) are handled without error or runaway.
 *
 * <p>Written once, without a test framework: the JUnit class students extend
 * ({@code org.kdtree.contract.KdTreeBuilderContract}) and the {@code grade} command run these
 * same cases.
 */
public final class Contract {
    /**
     * The longest one build of a contract scene may take ({@link Deadlines#GRADE}). The library's
     * builders need well under a second for any of them; a build still running after this is
     * stopped and reported as slow rather than left to slow the run down.
     */
    public static final long BUILD_SECONDS = (long) Deadlines.GRADE.buildSeconds();

    /** The tries of the two random-scene properties: jqwik's in the JUnit contract, seeded ones in grading. */
    public static final int RANDOM_2D_TRIES = 30, RANDOM_TRIANGLE_TRIES = 20;

    private Contract() {
    }

    /** {@return the contract's cases on fixed scenes, in the order a report lists them} */
    public static List<ContractCase> cases() {
        List<ContractCase> c = new ArrayList<>();
        c.add(new ContractCase("talk figures", b -> check(b.get(), BundledScenes.read2D("talk-figures.scene2d"), "the talk figures")));
        c.add(new ContractCase("mixed 2-D shapes", b -> check(b.get(), Shapes.named("mixed", 400), "400 mixed 2-D shapes")));
        c.add(new ContractCase("clustered 2-D shapes", b -> check(b.get(), Shapes.named("clustered", 300), "300 clustered 2-D triangles")));
        c.add(new ContractCase("uniform triangles", b -> check(b.get(), Meshes.named("uniform", 600), "600 uniform triangles")));
        c.add(new ContractCase("corner clusters", b -> check(b.get(), Meshes.cornerClusters(600, 4), "600 triangles in corner clusters")));
        c.add(new ContractCase("cube grid, faces in split planes", b -> check(b.get(), HardMeshes.cubeGrid(3), "a 3 x 3 x 3 grid of cubes")));
        c.add(new ContractCase("points in 1-D and 4-D", Contract::pointsIn1DAnd4D));
        c.add(new ContractCase("stops before the depth cap", Contract::stopsBeforeTheDepthCap));
        c.add(new ContractCase("empty scene", Contract::emptySceneGivesOneEmptyLeaf));
        c.add(new ContractCase("one primitive", Contract::onePrimitive));
        c.add(new ContractCase("10,000 identical triangles", Contract::identicalTrianglesStayBounded));
        c.add(new ContractCase("flat 3-D scene", b -> check(b.get(), Meshes.flat(300, 6), "300 triangles in one plane")));
        c.add(new ContractCase("flat 2-D scene", Contract::flatScene2D));
        c.add(new ContractCase("degenerate triangles", b -> check(b.get(), HardMeshes.degenerate(), "degenerate triangles")));
        c.add(new ContractCase("tiny and huge coordinates", Contract::tinyAndHugeCoordinates));
        c.add(new ContractCase("NaN coordinate rejected", Contract::nanCoordinateIsRejected));
        return c;
    }

    /**
     * The two random-scene properties with seeded tries, for a run without a property engine
     * (grading); the JUnit contract lets jqwik choose the sizes and seeds.
     * @return the two cases
     */
    public static List<ContractCase> randomCases() {
        return List.of(
                new ContractCase("any random 2-D scene (" + RANDOM_2D_TRIES + " tries)", b -> {
                    Random r = new Random(15);
                    for (int i = 0; i < RANDOM_2D_TRIES; i++) anyRandom2DScene(b.get(), r.nextInt(61), r.nextLong());
                }),
                new ContractCase("any random triangle soup (" + RANDOM_TRIANGLE_TRIES + " tries)", b -> {
                    Random r = new Random(16);
                    for (int i = 0; i < RANDOM_TRIANGLE_TRIES; i++) anyRandomTriangleSoup(b.get(), r.nextInt(81), r.nextLong());
                }));
    }

    /**
     * One try of the first property: n {@link Shapes#mixed mixed 2-D shapes}.
     * @param builder the builder
     * @param n 0 .. 60 shapes
     * @param seed the scene's seed
     */
    public static void anyRandom2DScene(KdTreeBuilder builder, int n, long seed) {
        check(builder, Shapes.mixed(n, seed), n + " mixed 2-D shapes (seed " + seed + ")");
    }

    /**
     * One try of the second property: a soup of n {@link Meshes#uniform(int, double, long) uniform triangles}.
     * @param builder the builder
     * @param n 0 .. 80 triangles
     * @param seed the scene's seed
     */
    public static void anyRandomTriangleSoup(KdTreeBuilder builder, int n, long seed) {
        check(builder, Meshes.uniform(n, 0.1, seed), n + " uniform triangles (seed " + seed + ")");
    }

    /**
     * Builds the tree of {@code prims} and checks every invariant of it.
     * @param builder the builder
     * @param prims the scene
     * @param scene the scene in words, for the messages
     * @return the tree, for further checks
     * @throws ContractViolation naming the invariant that broke
     */
    public static KdTree check(KdTreeBuilder builder, Primitives prims, String scene) {
        if (prims.size() > 50) requireStops(builder);
        KdTree tree = build(builder, prims, scene);
        TreeChecks.checkAll(builder, prims, tree);
        return tree;
    }

    /**
     * Builds the tree of {@code prims} under a {@link Supervisor} with this thread's deadlines
     * ({@link #deadlines()}): a builder that throws, answers with a plane the recursion cannot
     * use, hangs in a call or is too slow is reported as a violation with the builder's own
     * one-line {@link BuilderFault} message (its cause), and the scene.
     * @param builder the builder
     * @param prims the scene
     * @param scene the scene in words, for the messages
     * @return the tree
     */
    public static KdTree build(KdTreeBuilder builder, Primitives prims, String scene) {
        TreeTape tape = TAPE.get();
        try {
            if (tape != null && tape.takes(builder))
                return tape.build(builder, prims, scene, () -> Supervisor.of(deadlines()).build(builder, prims));
            return Supervisor.of(deadlines()).build(builder, prims);
        } catch (BuilderFault fault) {
            throw new ContractViolation(fault.getMessage() + " (building " + scene + ")", fault);
        }
    }

    private static final ThreadLocal<TreeTape> TAPE = new ThreadLocal<>();

    /**
     * Runs {@code body} with every build of {@code tape}'s builder on this thread recorded into
     * it or replayed from it (grading in a box: {@link TreeTape}).
     * @param tape the tape
     * @param body the checks to run
     */
    public static void withTape(TreeTape tape, Runnable body) {
        with(TAPE, tape, body);
    }

    private static final ThreadLocal<Deadlines> DEADLINES = ThreadLocal.withInitial(() -> Deadlines.GRADE);

    /** {@return the deadlines of the builds this thread makes: {@link Deadlines#GRADE} unless {@link #withDeadlines} says otherwise} */
    public static Deadlines deadlines() {
        return DEADLINES.get();
    }

    /**
     * Runs {@code body} with {@code deadlines} for every build it makes on this thread (grade's
     * {@code --call-deadline} and {@code --build-deadline}).
     * @param deadlines how long a call and a build may take
     * @param body the checks to run
     */
    public static void withDeadlines(Deadlines deadlines, Runnable body) {
        with(DEADLINES, deadlines, body);
    }

    /** Runs {@code body} with {@code local} set to {@code value} on this thread, then puts back what it held (the one way of both). */
    private static <T> void with(ThreadLocal<T> local, T value, Runnable body) {
        T before = local.get();
        local.set(value);
        try {
            body.run();
        } finally {
            local.set(before);
        }
    }

    private static void pointsIn1DAnd4D(Supplier<? extends KdTreeBuilder> b) {
        check(b.get(), Points.uniform(200, 1, 5), "200 points in 1-D");
        check(b.get(), Points.grid(100, 4, 5), "100 points on a grid in 4-D");
    }

    /**
     * A builder that never returns true from terminate() splits empty voxels down to the depth
     * cap: 2^cap leaves, tolerable on 50 shapes and hopeless on real scenes.
     */
    private static void stopsBeforeTheDepthCap(Supplier<? extends KdTreeBuilder> b) {
        ContractViolation v = stopping(b.get());
        if (v != null) throw v;
    }

    /**
     * Checks that the builder stops on its own, once per builder class, before any scene big
     * enough for a never-stopping builder to take long: so such a builder fails at once, with
     * that message, rather than slowing every check down.
     * @param builder the builder
     * @throws ContractViolation if it splits empty nodes of 50 random shapes
     */
    public static void requireStops(KdTreeBuilder builder) {
        TreeTape tape = TAPE.get();
        Map<Class<?>, Optional<ContractViolation>> stops = tape != null && tape.takes(builder) ? tape.stops : STOPS;
        ContractViolation v = stops.computeIfAbsent(builder.getClass(), c -> Optional.ofNullable(stopping(builder))).orElse(null);
        if (v != null) throw new ContractViolation(v.getMessage());
    }

    /** Per builder class, whether it stops; a tape keeps its own (a replay's stand-in class is every student's). */
    private static final Map<Class<?>, Optional<ContractViolation>> STOPS = new ConcurrentHashMap<>();

    private static ContractViolation stopping(KdTreeBuilder builder) {
        Scene2D scene = Shapes.mixed(50, 11);
        KdTree tree = build(builder, scene, "50 mixed 2-D shapes");
        TreeChecks.checkAll(builder, scene, tree);
        int[] emptySplits = {0};
        referencesBelow(tree, 0, emptySplits);
        if (emptySplits[0] == 0) return null;
        return new ContractViolation(builder.name() + " never stops: on 50 mixed 2-D shapes it split " + emptySplits[0]
                + " nodes holding no primitive, down to the depth cap (" + builder.depthCap(scene.size()) + ");"
                + " terminate() must return true once a node is small enough (an empty node at the latest).");
    }

    /** The references in the leaves below {@code node}; counts the interior nodes with none in {@code emptySplits}. */
    private static long referencesBelow(KdTree tree, int node, int[] emptySplits) {
        if (tree.isLeaf(node)) return tree.leafSize(node);
        long below = referencesBelow(tree, tree.leftChild(node), emptySplits) + referencesBelow(tree, tree.rightChild(node), emptySplits);
        if (below == 0) emptySplits[0]++;
        return below;
    }

    private static void emptySceneGivesOneEmptyLeaf(Supplier<? extends KdTreeBuilder> b) {
        KdTreeBuilder builder = b.get();
        KdTree tree = check(builder, new TriangleMesh(new double[0], new int[0]), "an empty scene");
        ContractViolation.require(tree.nodeCount() == 1, builder.name() + ": the tree of an empty scene has "
                + tree.nodeCount() + " nodes; it must be one empty leaf.");
        ContractViolation.require(tree.stats().references() == 0, builder.name() + ": the tree of an empty scene lists "
                + tree.stats().references() + " references; it must list none.");
    }

    private static void onePrimitive(Supplier<? extends KdTreeBuilder> b) {
        KdTreeBuilder builder = b.get();
        KdTree tree = check(builder, HardMeshes.soup(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}), "one triangle");
        ContractViolation.require(tree.stats().references() > 0,
                builder.name() + ": a scene of one triangle gave a tree listing it in no leaf.");
        check(b.get(), new Scene2D(List.of(new Shape2D.Segment(0, 0, 3, 1))), "one 2-D segment");
    }

    private static void identicalTrianglesStayBounded(Supplier<? extends KdTreeBuilder> b) {
        KdTreeBuilder builder = b.get();
        TriangleMesh copies = HardMeshes.identical(10_000);
        KdTree tree = check(builder, copies, "10,000 identical triangles");
        long refs = tree.stats().references();
        ContractViolation.require(refs <= 64L * copies.size(), builder.name() + ": the tree of 10,000 identical triangles lists "
                + refs + " references, more than 64 per triangle; memory must stay bounded.");
    }

    private static void flatScene2D(Supplier<? extends KdTreeBuilder> b) {
        List<Shape2D> onALine = new ArrayList<>();
        for (int i = 0; i < 50; i++) onALine.add(new Shape2D.Segment(i, 5, i + 0.5, 5));
        onALine.add(new Shape2D.Point(7.25, 5));
        check(b.get(), new Scene2D(onALine), "50 segments on one line");
    }

    private static void tinyAndHugeCoordinates(Supplier<? extends KdTreeBuilder> b) {
        check(b.get(), HardMeshes.scaled(Meshes.cornerClusters(300, 7), 1e-6), "300 triangles scaled by 1e-6");
        check(b.get(), HardMeshes.scaled(Meshes.cornerClusters(300, 7), 1e6), "300 triangles scaled by 1e6");
    }

    private static void nanCoordinateIsRejected(Supplier<? extends KdTreeBuilder> b) {
        KdTreeBuilder builder = b.get();
        try {
            build(builder, new NaNAt(3), "five points, one with a NaN coordinate");
        } catch (InvalidGeometryException e) {
            ContractViolation.require(e.getMessage().contains("primitive 3"), builder.name()
                    + ": a NaN coordinate must be rejected with a message naming the primitive (3), not: " + e.getMessage());
            return;
        }
        throw new ContractViolation(builder.name() + ": a scene with a NaN coordinate (primitive 3) was built;"
                + " it must be rejected with an InvalidGeometryException naming the primitive.");
    }

    /** Five 2-D points, the fourth of which (index 3) has a NaN coordinate. */
    private static final class NaNAt implements Primitives {
        private final int bad;

        NaNAt(int bad) { this.bad = bad; }

        @Override public int dimension() { return 2; }
        @Override public int size() { return 5; }
        @Override public void bounds(int i, org.kdtree.geom.Box d) {
            double x = i == bad ? Double.NaN : i;
            d.setMin(0, x).setMax(0, x).setMin(1, 0).setMax(1, 0);
        }
        @Override public void clip(int i, org.kdtree.geom.Box voxel, org.kdtree.geom.Box d) { bounds(i, d); d.intersect(voxel); }
    }
}
