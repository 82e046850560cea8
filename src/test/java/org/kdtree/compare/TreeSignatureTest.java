package org.kdtree.compare;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.kdtree.generate.Meshes;
import org.kdtree.generate.Shapes;
import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.SahBuilder;
import org.kdtree.kdtree.SlidingMidpointBuilder;
import org.kdtree.kdtree.TreeVisitor;
import org.kdtree.shape.PointsKd;

/**
 * A signature is a normalised picture of its tree: equal data gives equal signatures (distance
 * 0), the same data shifted and scaled gives a distance within {@link #SHIFT_SCALE_TOLERANCE},
 * the occupancy grid is what brute force over every leaf and cell gives, and a signature survives
 * its bytes.
 */
class TreeSignatureTest {
    /** The distance the docs state for a set and its shifted, uniformly scaled copy. */
    static final double SHIFT_SCALE_TOLERANCE = 1e-6;

    @ParameterizedTest(name = "{0}-D")
    @ValueSource(ints = {2, 3, 5, 12, 20})
    void equalDataIsAtZero(int k) {
        for (int f = 0; f < Families.NAMES.size(); f++) {
            PointsKd p = Families.instance(f, 1500, k, 7 + f);
            TreeSignature a = Families.signature(p), b = Families.signature(Families.moved(p, 1, new double[k]));
            assertThat(TreeDistance.of(a, b)).as(Families.NAMES.get(f)).isZero();
            assertThat(a.occupancy()).isEqualTo(b.occupancy());
            assertThat(Arrays.stream(a.volumes()).sum()).isCloseTo(1, within(1e-9));
            assertThat(Arrays.stream(a.depths()).sum()).isCloseTo(1, within(1e-9));
        }
    }

    @ParameterizedTest(name = "{0}-D")
    @ValueSource(ints = {2, 5})
    void shiftedAndScaledDataIsWithinTheTolerance(int k) {
        double worst = 0;
        for (int f = 0; f < Families.NAMES.size(); f++)
            for (int i = 0; i < 5; i++) {
                PointsKd p = Families.instance(f, 2000, k, 31 * f + i);
                TreeDistance d = TreeDistance.between(Families.signature(p), Families.signature(Families.moved(p, 17 * f + i)));
                worst = Math.max(worst, d.total());
                assertThat(d.total()).as("%s #%d: terms %s", Families.NAMES.get(f), i, Arrays.toString(d.terms()))
                        .isLessThanOrEqualTo(SHIFT_SCALE_TOLERANCE);
            }
        System.out.printf("%d-D: the worst shifted and scaled copy is at %.2e%n", k, worst);
    }

    @Test void differentFamiliesAreFarApart() {
        TreeSignature uniform = Families.signature(Families.instance(0, 2000, 2, 1));
        TreeSignature line = Families.signature(Families.instance(4, 2000, 2, 1));
        TreeDistance d = TreeDistance.between(uniform, line);
        assertThat(d.total()).isGreaterThan(0.3).isLessThanOrEqualTo(1);
        assertThat(TreeDistance.of(line, uniform)).isEqualTo(d.total());
        for (double t : d.terms()) assertThat(t).isBetween(0.0, 1.0);
    }

    @Test void treesOverShapesAndMeshesHaveSignaturesToo() {
        KdTree shapes = new SahBuilder().build(Shapes.uniform(300, 3));
        KdTree mesh = new SahBuilder().build(Meshes.named("clustered", 2000));
        for (KdTree t : List.of(shapes, mesh)) {
            TreeSignature s = TreeSignature.of(t);
            assertThat(s.dimension()).isEqualTo(t.dimension());
            assertThat(Arrays.stream(s.volumes()).sum()).isCloseTo(1, within(1e-9));
            assertThat(TreeDistance.of(s, TreeSignature.of(t))).isZero();
        }
        assertThatThrownBy(() -> TreeDistance.of(TreeSignature.of(shapes), TreeSignature.of(mesh)))
                .isInstanceOf(IllegalArgumentException.class).hasMessageContaining("2-D and 3-D");
    }

    /** The grid's cells against brute force: every leaf's overlap with every cell, from the boxes. */
    @ParameterizedTest(name = "{0}-D")
    @ValueSource(ints = {2, 3, 5, 14})
    void theOccupancyIsTheMeanDepthOfTheLeavesOverEachCell(int k) {
        PointsKd p = Families.moved(Families.instance(1, 600, k, 3), 5);
        KdTree tree = new SlidingMidpointBuilder().build(p);
        TreeSignature s = TreeSignature.of(tree);
        double[] expected = bruteForceOccupancy(tree, s);
        double[] actual = s.occupancy();
        for (int c = 0; c < expected.length; c++) assertThat(actual[c]).as("cell %d", c).isCloseTo(expected[c], within(1e-9));
        assertThat(Arrays.stream(actual).max().orElse(0)).isGreaterThan(0);
    }

    private static double[] bruteForceOccupancy(KdTree tree, TreeSignature s) {
        Box root = tree.bounds();
        int k = root.dimension(), axes = s.gridAxes(), side = s.cellsPerAxis();
        double longest = 0;
        for (int a = 0; a < k; a++) longest = Math.max(longest, root.extent(a));
        double[] lo = new double[k], hi = new double[k];
        List<double[]> leaves = new ArrayList<>();   // min corner, max corner, depth: normalised
        double l = longest;
        tree.walk(new TreeVisitor() {
            @Override public void interior(int node, int depth, Box voxel, int axis, double split) { }

            @Override public void leaf(int node, int depth, Box voxel, int from, int to) {
                double[] leaf = new double[2 * k + 1];
                for (int a = 0; a < k; a++) {
                    double c = (root.min(a) + root.max(a)) / 2;
                    leaf[a] = (voxel.min(a) - c) / l + 0.5;
                    leaf[k + a] = (voxel.max(a) - c) / l + 0.5;
                }
                leaf[2 * k] = depth;
                leaves.add(leaf);
            }
        });
        double[] cells = new double[s.occupancy().length];
        for (int c = 0; c < cells.length; c++) {
            for (int a = 0, rest = c; a < axes; a++, rest /= side) {
                lo[a] = (rest % side) / (double) side;
                hi[a] = lo[a] + 1.0 / side;
            }
            for (double[] leaf : leaves) {
                double share = 1;
                for (int a = 0; a < k; a++) {
                    double e = root.extent(a) / l;
                    share *= a < axes ? Math.max(0, Math.min(hi[a], leaf[k + a]) - Math.max(lo[a], leaf[a])) * side
                            : (leaf[k + a] - leaf[a]) / e;
                }
                cells[c] += share * leaf[2 * k];
            }
        }
        return cells;
    }

    @Test void aSignatureSurvivesItsBytes() {
        TreeSignature s = Families.signature(Families.instance(2, 1000, 3, 9));
        TreeSignature back = TreeSignature.fromBytes(s.toBytes());
        assertThat(TreeDistance.of(s, back)).isZero();
        assertThat(back.occupancy()).isEqualTo(s.occupancy());
        assertThat(back.splits()).isEqualTo(s.splits());
        assertThat(back.leaves()).isEqualTo(s.leaves());
        byte[] bytes = s.toBytes();
        assertThatThrownBy(() -> TreeSignature.fromBytes(Arrays.copyOf(bytes, bytes.length - 3)))
                .isInstanceOf(IllegalArgumentException.class);
        byte[] other = bytes.clone();
        other[7] = 9;   // the version
        assertThatThrownBy(() -> TreeSignature.fromBytes(other)).isInstanceOf(IllegalArgumentException.class);
        Random r = new Random(1);
        for (int i = 0; i < 200; i++) {   // any damage: refused or read, never thrown otherwise
            byte[] damaged = bytes.clone();
            damaged[r.nextInt(damaged.length)] ^= (byte) (1 << r.nextInt(8));
            try {
                TreeSignature.fromBytes(damaged);
            } catch (IllegalArgumentException expected) {
                // refused in one message
            }
        }
    }
}
