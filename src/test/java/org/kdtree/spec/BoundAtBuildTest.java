package org.kdtree.spec;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.Random;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.BruteForce;
import org.kdtree.accel.Hit;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TraversalStats;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.generate.Meshes;
import org.kdtree.generate.Points;
import org.kdtree.geom.Box;
import org.kdtree.geom.Ray;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.TriangleMesh;
import org.junit.jupiter.api.Test;

/**
 * The mesh is bound once, when a structure is built: its queries take no second copy of it, so
 * they cannot be handed another mesh; and no method hands out a structure's own arrays.
 */
class BoundAtBuildTest {
    @Test void everyStructureTracesTheMeshItWasBuiltOver() {
        TriangleMesh built = Meshes.uniform(400, 5), other = Meshes.uniform(400, 6);
        BruteForce brute = new BruteForce(new TriangleIntersector(built));
        for (String name : new String[] {"sah", "median-plane", "bvh"}) {
            AccelerationStructure s = BuilderSpec.of(name).build(built, null);
            RayQuery fast = s.query(), listened = s.query(new TraversalStats());
            Random r = new Random(7);
            Box b = built.bounds();
            Ray ray = new Ray(3);
            int hits = 0;
            for (int i = 0; i < 300; i++) {
                double[] o = new double[3], d = new double[3];
                for (int a = 0; a < 3; a++) {
                    o[a] = b.min(a) + (b.max(a) - b.min(a)) * r.nextDouble();
                    d[a] = r.nextGaussian();
                }
                ray.set(o[0], o[1], o[2], d[0], d[1], d[2]);
                Hit want = new Hit(), got = new Hit(), heard = new Hit();
                boolean w = brute.closestHit(ray, 0, Double.POSITIVE_INFINITY, want);
                assertThat(fast.closestHit(ray, 0, Double.POSITIVE_INFINITY, got)).as("%s ray %d", name, i).isEqualTo(w);
                assertThat(listened.closestHit(ray, 0, Double.POSITIVE_INFINITY, heard)).as("%s ray %d", name, i).isEqualTo(w);
                if (w) {
                    hits++;
                    assertThat(got.primitive).as("%s ray %d", name, i).isEqualTo(want.primitive);
                    assertThat(got.t).as("%s ray %d", name, i).isEqualTo(want.t);
                    assertThat(heard.primitive).as("%s ray %d", name, i).isEqualTo(want.primitive);
                }
            }
            assertThat(hits).as("%s: rays from inside the cloud hit", name).isGreaterThan(100);
            assertThat(other.size()).isEqualTo(built.size());   // the other mesh has no way in: query() takes nothing
        }
    }

    @Test void aTreeOverPointsSaysItAnswersPointQueriesNotRays() {
        KdTree points = Builders.create("sliding-midpoint").build(Points.uniform(100, 3, 1));
        assertThatThrownBy(points::query).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("not PointsKd").hasMessageContaining("PointTree");
    }

    @Test void aTreesArraysAreCopiesNotTheTreesOwn() {
        KdTree tree = Builders.create("sah").build(Meshes.uniform(200, 3));
        int[] nodes = tree.nodeArray(), refs = tree.refArray();
        int[] nodesBefore = nodes.clone(), refsBefore = refs.clone();
        java.util.Arrays.fill(nodes, -1);
        java.util.Arrays.fill(refs, -1);
        assertThat(tree.nodeArray()).isEqualTo(nodesBefore);
        assertThat(tree.refArray()).isEqualTo(refsBefore);
        assertThat(tree.isLeaf(0)).isFalse();
    }
}
