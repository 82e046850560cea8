package org.kdtree.contract;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.junit.jupiter.api.Test;
import org.kdtree.build.KdTreeBuilder;
import org.kdtree.geom.Box;
import org.kdtree.shape.InvalidGeometryException;
import org.kdtree.shape.PointsKd;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.Shape2D;
import org.kdtree.shape.Shapes2D;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.testing.TestScenes;
import org.kdtree.tree.KdTree;

/**
 * The contract every {@link KdTreeBuilder} must honour: extend this class, implement
 * {@link #newBuilder()}, and JUnit runs every check below on 2-D and 3-D scenes, the hard
 * inputs included. A failure says, in words, which invariant broke and where.
 *
 * <pre>
 * class MyBuilderTest extends KdTreeBuilderContract {
 *     &#64;Override protected KdTreeBuilder newBuilder() { return new MyBuilder(); }
 * }
 * </pre>
 *
 * The invariants: every primitive is listed in every leaf whose voxel it overlaps and in no
 * other; the leaves tile the root voxel; every split plane lies inside its voxel; no leaf is
 * deeper than the depth cap; hard inputs (empty scene, one primitive, 10,000 identical
 * triangles, flat scenes, degenerate triangles, NaN) are handled without error or runaway.
 */
public abstract class KdTreeBuilderContract {
    /** A new builder with the settings under test. */
    protected abstract KdTreeBuilder newBuilder();

    /** Builds and checks every invariant; returns the tree for further checks. */
    protected KdTree buildAndCheck(Primitives prims) {
        KdTreeBuilder b = newBuilder();
        KdTree tree = b.build(prims);
        TreeChecks.checkAll(b, prims, tree);
        return tree;
    }

    // ---- ordinary scenes ----

    @Test void talkFigureScene() { buildAndCheck(TestScenes.talkFigures()); }

    @Test void random2DShapes() { buildAndCheck(TestScenes.random2D(400, 1)); }

    @Test void clustered2D() { buildAndCheck(TestScenes.clustered2D(300, 2)); }

    @Test void randomTriangles3D() { buildAndCheck(TestScenes.randomTriangles(600, 0.05, 3)); }

    @Test void clusteredTriangles3D() { buildAndCheck(TestScenes.clusteredTriangles(600, 4)); }

    @Test void cubeGridWithFacesInSplitPlanes() { buildAndCheck(TestScenes.cubeGrid(3)); }

    @Test void pointsIn1DAnd4D() {
        double[] one = new double[200], four = new double[400];
        java.util.Random r = new java.util.Random(5);
        for (int i = 0; i < one.length; i++) one[i] = r.nextDouble();
        for (int i = 0; i < four.length; i++) four[i] = r.nextInt(10);
        buildAndCheck(new PointsKd(1, one));
        buildAndCheck(new PointsKd(4, four));
    }

    // ---- hard inputs ----

    @Test void emptySceneGivesOneEmptyLeaf() {
        KdTree tree = buildAndCheck(new TriangleMesh(new double[0], new int[0]));
        assertThat(tree.nodeCount()).as("nodes of the tree of an empty scene").isEqualTo(1);
        assertThat(tree.stats().references()).as("references in the tree of an empty scene").isZero();
    }

    @Test void onePrimitive() {
        KdTree tree = buildAndCheck(TestScenes.soup(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}));
        assertThat(tree.stats().references()).as("a single triangle is listed in at least one leaf").isPositive();
        buildAndCheck(new Shapes2D(List.of(new Shape2D.Segment(0, 0, 3, 1))));
    }

    @Test void tenThousandIdenticalTrianglesEndQuicklyAndBounded() {
        TriangleMesh copies = TestScenes.identicalTriangles(10_000);
        KdTree tree = assertTimeoutPreemptively(Duration.ofSeconds(30), () -> buildAndCheck(copies),
                "building 10,000 identical triangles must end quickly (the depth cap stops it)");
        assertThat(tree.stats().references())
                .as("references for 10,000 coincident triangles: memory must stay bounded")
                .isLessThanOrEqualTo(64L * copies.size());
    }

    @Test void flatScene3D() { buildAndCheck(TestScenes.flatTriangles(300, 6)); }

    @Test void flatScene2D() {
        List<Shape2D> onALine = new ArrayList<>();
        for (int i = 0; i < 50; i++) onALine.add(new Shape2D.Segment(i, 5, i + 0.5, 5));
        onALine.add(new Shape2D.Point(7.25, 5));
        buildAndCheck(new Shapes2D(onALine));
    }

    @Test void degenerateTriangles() { buildAndCheck(TestScenes.degenerateTriangles()); }

    @Test void tinyAndHugeCoordinates() {
        buildAndCheck(TestScenes.scaled(TestScenes.clusteredTriangles(300, 7), 1e-6));
        buildAndCheck(TestScenes.scaled(TestScenes.clusteredTriangles(300, 7), 1e6));
    }

    @Test void nanCoordinateIsRejectedNamingThePrimitive() {
        Primitives withNaN = new NaNAt(3);
        assertThatThrownBy(() -> newBuilder().build(withNaN))
                .as("a NaN coordinate must be rejected with a message naming the primitive")
                .isInstanceOf(InvalidGeometryException.class)
                .hasMessageContaining("primitive 3");
    }

    // ---- properties on random scenes ----

    @Property(tries = 30)
    void anyRandom2DScene(@ForAll @IntRange(min = 0, max = 60) int n, @ForAll long seed) {
        buildAndCheck(TestScenes.random2D(n, seed));
    }

    @Property(tries = 20)
    void anyRandomTriangleSoup(@ForAll @IntRange(min = 0, max = 80) int n, @ForAll long seed) {
        buildAndCheck(TestScenes.randomTriangles(n, 0.1, seed));
    }

    /** Five 2-D points, the fourth of which (index 3) has a NaN coordinate. */
    private static final class NaNAt implements Primitives {
        private final int bad;

        NaNAt(int bad) { this.bad = bad; }

        @Override public int dimension() { return 2; }
        @Override public int size() { return 5; }
        @Override public void bounds(int i, Box d) {
            double x = i == bad ? Double.NaN : i;
            d.setMin(0, x).setMax(0, x).setMin(1, 0).setMax(1, 0);
        }
        @Override public void clip(int i, Box voxel, Box d) { bounds(i, d); d.intersect(voxel); }
    }
}
