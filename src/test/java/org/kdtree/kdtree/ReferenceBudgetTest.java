package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Ray;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.spec.Builders;

/**
 * Geometry that overlaps without end stays bounded: one polygon of 30,000 vertices on a circle,
 * fan-triangulated into 29,998 slivers that all share a vertex, used to make a 25-million-node
 * tree at 10,000 vertices. Every builder stops within its reference budget, says how many leaves
 * it made early, and still answers rays as brute force does.
 */
class ReferenceBudgetTest {
    private static final int VERTICES = 30_000;
    private static final TriangleMesh FAN = fan(VERTICES);

    @Test void everyBuilderStaysWithinItsBudgetOnAFanOfSlivers() {
        TriangleIntersector tris = new TriangleIntersector(FAN);
        for (String name : Builders.names()) {
            KdTree tree = Builders.create(name).build(FAN);
            long budget = (long) KdTreeBuilder.REFERENCE_BUDGET.defaultValue() * FAN.size();
            assertThat((long) tree.refArray().length).as("%s: references", name).isLessThanOrEqualTo(budget);
            assertThat(tree.budgetLeaves()).as("%s: leaves made early", name).isPositive();
            Oracle oracle = new Oracle(tris, tree, name);
            Random r = new Random(5);
            for (int i = 0; i < 300; i++) {
                double x = 2 * r.nextDouble() - 1, y = 2 * r.nextDouble() - 1;
                oracle.check(new Ray(new double[] {x, y, 1}, new double[] {0.01 * r.nextGaussian(), 0.01 * r.nextGaussian(), -1}));
            }
        }
    }

    @Test void aHundredThousandCoincidentTrianglesMakeOneLeafWithEveryBuilder() {
        int n = 100_000;
        double[] v = {0, 0, 0, 1, 0, 0.5, 0, 1, 1};
        int[] idx = new int[3 * n];
        for (int t = 0; t < n; t++) { idx[3 * t] = 0; idx[3 * t + 1] = 1; idx[3 * t + 2] = 2; }
        TriangleMesh same = new TriangleMesh(v, idx);
        for (String name : Builders.names()) {
            KdTree tree = Builders.create(name).build(same);
            assertThat(tree.refArray().length).as("%s: references", name).isEqualTo(n);
            assertThat(tree.nodeCount()).as("%s: nodes", name).isLessThanOrEqualTo(3);
        }
    }

    /**
     * The SAH stops by itself where splitting stops paying, so the default budget never binds on
     * a mesh (the bunny's exact tree holds 5.3 references per triangle). The median builders,
     * which split on to the depth cap, do meet it at a sphere's poles: fans of 60 slivers.
     */
    @Test void theDefaultBudgetLeavesTheSahTreeOfAMeshAlone() {
        TriangleMesh sphere = Scenes.sphere(0, 0, 0, 1, 40, 60);
        assertThat(Builders.create("sah").build(sphere).budgetLeaves()).isZero();
        assertThat(Builders.create("median-plane").build(sphere).budgetLeaves()).isPositive();
    }

    private static TriangleMesh fan(int n) {
        double[] v = new double[3 * n];
        for (int i = 0; i < n; i++) {
            double a = 2 * Math.PI * i / n;
            v[3 * i] = Math.cos(a);
            v[3 * i + 1] = Math.sin(a);
        }
        int[] idx = new int[3 * (n - 2)];
        for (int t = 0; t < n - 2; t++) {
            idx[3 * t] = 0;
            idx[3 * t + 1] = t + 1;
            idx[3 * t + 2] = t + 2;
        }
        return new TriangleMesh(v, idx);
    }
}
