package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.EnumMap;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.Hit;
import org.kdtree.accel.TraversalListener.Visit;
import org.kdtree.accel.TraversalListener;
import org.kdtree.geom.Ray;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.spec.Builders;

/**
 * Algorithm 2's decision at an interior node, case by case (Havran's list): {@code decide}, which
 * the generic loop calls (2-D shapes, k-D, any query with a listener), and the 3-D loop's inlined
 * copy of it, which must decide alike.
 */
class DecideTest {
    @Test void theThreeCasesOfTheTalk() {
        assertThat(Traverser.decide(5, 1, 3)).isEqualTo(Visit.NEAR);
        assertThat(Traverser.decide(0.5, 1, 3)).isEqualTo(Visit.FAR);
        assertThat(Traverser.decide(2, 1, 3)).isEqualTo(Visit.BOTH);
    }

    @Test void tiesVisitBothChildren() {
        assertThat(Traverser.decide(1, 1, 3)).isEqualTo(Visit.BOTH);
        assertThat(Traverser.decide(3, 1, 3)).isEqualTo(Visit.BOTH);
        assertThat(Traverser.decide(Math.nextUp(3.0), 1, 3)).as("within rounding").isEqualTo(Visit.BOTH);
        assertThat(Traverser.decide(0, 0, 0)).as("origin on the plane, empty-length interval").isEqualTo(Visit.BOTH);
        assertThat(Traverser.decide(-0.0, 0, 3)).isEqualTo(Visit.BOTH);
    }

    @Test void raysParallelToThePlaneVisitOneChildRaysInItVisitBoth() {
        assertThat(Traverser.decide(Double.POSITIVE_INFINITY, 1, 3)).isEqualTo(Visit.NEAR);
        assertThat(Traverser.decide(Double.NEGATIVE_INFINITY, 1, 3)).isEqualTo(Visit.FAR);
        assertThat(Traverser.decide(0.0 * Double.POSITIVE_INFINITY, 1, 3)).isEqualTo(Visit.BOTH_IN_PLANE);
    }

    /**
     * The 3-D loop ({@code MeshTraversal}) writes the decision inline, for speed. Over Havran's hard
     * scene and directions it must find exactly the closest hit the generic loop finds, while the
     * generic loop, through {@code decide}, meets every case.
     */
    @Test void theThreeDLoopDecidesAsDecideDoes() {
        TriangleMesh mesh = HardCases3DTest.boxes();
        KdTree tree = Builders.create("sah").build(mesh);
        Traverser t = new Traverser(tree);
        Map<Visit, Integer> seen = new EnumMap<>(Visit.class);
        TraversalListener counting = new TraversalListener() {
            @Override public void interior(int node, int axis, double split, double tMin, double tMax, double tSplit,
                                           int near, int far, Visit visit) {
                seen.merge(visit, 1, Integer::sum);
            }
        };
        Ray ray = new Ray(3);
        Hit fast = new Hit(), generic = new Hit();
        int hits = 0;
        for (double x = -1; x <= 5; x += 0.5)
            for (double y = -1; y <= 5; y += 1)
                for (double z = 0; z <= 4; z += 1)
                    for (double[] d : HardCases3DTest.directions()) {
                        ray.set(x, y, z, d[0], d[1], d[2]);
                        boolean f = t.closestHit(ray, 0, Double.POSITIVE_INFINITY, fast);
                        boolean g = t.closestHit(ray, 0, Double.POSITIVE_INFINITY, generic, counting);
                        assertThat(f).as("hit from (%s, %s, %s)", x, y, z).isEqualTo(g);
                        if (!g) continue;
                        hits++;
                        assertThat(fast.t).isEqualTo(generic.t);
                        assertThat(fast.primitive).isEqualTo(generic.primitive);
                    }
        assertThat(hits).isGreaterThan(1000);
        assertThat(seen.keySet()).containsExactlyInAnyOrder(Visit.values());
    }
}
