package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import net.jqwik.api.constraints.IntRange;
import org.kdtree.accel.Hit;
import org.kdtree.accel.Intersector;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.geom.Ray;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.testing.GridArbitraries;

/**
 * Random scenes and rays, for every builder, against brute force. Coordinates are drawn from a
 * coarse grid (multiples of 1/4 in [0, 4]) so that coincident planes, shared vertices, planar and
 * degenerate triangles, and rays in split planes or through vertices come up often.
 */
class TraversalPropertiesTest {
    @Provide Arbitrary<Double> coord() { return GridArbitraries.coord(); }

    @Provide Arbitrary<double[]> point() { return GridArbitraries.point(); }

    @Provide Arbitrary<List<double[]>> triangles() { return GridArbitraries.triangles(); }

    @Provide Arbitrary<double[]> direction() {
        Arbitrary<Double> c = Arbitraries.of(0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 0.25, 2.0, -3.0);
        return Combinators.combine(c, c, c).as((x, y, z) -> new double[] {x, y, z})
                .filter(d -> d[0] != 0 || d[1] != 0 || d[2] != 0);
    }

    @Property(tries = 150)
    void closestAnyAndAllHitsAgreeWithBruteForce3D(@ForAll("triangles") List<double[]> tris,
                                                    @ForAll("point") double[] origin,
                                                    @ForAll("direction") double[] dir,
                                                    @ForAll @IntRange(max = 1000) int vertexPick) {
        TriangleMesh mesh = mesh(tris);
        TriangleIntersector x = new TriangleIntersector(mesh);
        Ray ray = new Ray(3);
        double[] v = tris.get(vertexPick % tris.size());
        int corner = 3 * (vertexPick % 3);
        for (Oracle o : Oracle.allBuilders(mesh, x)) {
            ray.set(origin[0], origin[1], origin[2], dir[0], dir[1], dir[2]);
            o.check(ray);
            o.check(ray, 0.25, 1.5);
            // Through a vertex of the scene, from the origin (skipped when they coincide).
            double dx = v[corner] - origin[0], dy = v[corner + 1] - origin[1], dz = v[corner + 2] - origin[2];
            if (dx != 0 || dy != 0 || dz != 0) {
                ray.set(origin[0], origin[1], origin[2], dx, dy, dz);
                o.check(ray);
                if (o.traverser == null) continue;      // all hits: a kd-tree's query only
                List<Hit> all = o.traverser.allHits(ray, 0, Double.POSITIVE_INFINITY);
                int expected = 0;
                for (int p = 0; p < x.size(); p++) if (x.intersect(p, ray, 0, Double.POSITIVE_INFINITY, new Hit())) expected++;
                assertThat(all).hasSize(expected);
            }
        }
    }

    @Provide Arbitrary<Double> coord2() {
        return Arbitraries.integers().between(0, 8).map(i -> i / 2.0);
    }

    @Provide Arbitrary<Shape2D> shape() {
        Arbitrary<Double> c = coord2();
        return Arbitraries.oneOf(
                Combinators.combine(c, c).as(Shape2D.Point::new),
                Combinators.combine(c, c, c, c).as(Shape2D.Segment::new),
                Combinators.combine(c, c, c, c).as(Shape2D.Rect::new),
                Combinators.combine(c, c, c, c, c, c).as(Shape2D.Triangle::new));
    }

    @Property(tries = 150)
    void closestAndAnyHitAgreeWithBruteForce2D(@ForAll("shapes2D") List<Shape2D> shapes,
                                                @ForAll("coord2") double ox, @ForAll("coord2") double oy,
                                                @ForAll("direction") double[] dir) {
        if (dir[0] == 0 && dir[1] == 0) return;
        Scene2D scene = new Scene2D(shapes);
        Ray ray = new Ray(2).set(ox, oy, dir[0], dir[1]);
        for (Oracle o : Oracle.allBuilders(scene, Intersector.of(scene))) {
            o.check(ray);
            o.check(ray, 0.5, 2);
        }
    }

    @Provide Arbitrary<List<Shape2D>> shapes2D() {
        return shape().list().ofMinSize(1).ofMaxSize(30);
    }

    private static TriangleMesh mesh(List<double[]> tris) {
        MeshBuilder b = new MeshBuilder();
        for (double[] t : tris)
            b.triangle(new double[] {t[0], t[1], t[2]}, new double[] {t[3], t[4], t[5]}, new double[] {t[6], t[7], t[8]});
        return b.build();
    }

}
