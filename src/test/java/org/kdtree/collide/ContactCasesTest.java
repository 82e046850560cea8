package org.kdtree.collide;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.testing.TestScenes;

/**
 * Exact contacts, built from small integers and halves so that every product is exact: a sphere
 * exactly touching a face, an edge or a vertex overlaps; one a hair further away does not; a
 * moving sphere grazing an edge or a vertex touches it at the tangent moment (the grazing rule:
 * contacts are closed). Every case runs on trees from every builder, against brute force.
 */
class ContactCasesTest {
    /** The triangle (0,0,0), (4,0,0), (0,4,0) in z = 0, plus a far one so the trees have splits. */
    private static TriangleMesh floor() {
        List<double[]> t = new ArrayList<>();
        t.add(new double[] {0, 0, 0, 4, 0, 0, 0, 4, 0});
        t.add(new double[] {10, 10, 10, 11, 10, 10, 10, 11, 10});
        t.add(new double[] {-10, 5, 3, -9, 5, 3, -10, 6, 4});
        double[] v = new double[9 * t.size()];
        for (int i = 0; i < t.size(); i++) System.arraycopy(t.get(i), 0, v, 9 * i, 9);
        return TestScenes.soup(v);
    }

    private static List<CollideOracle> oracles3() {
        TriangleMesh m = floor();
        return CollideOracle.allBuilders(m, new MeshCollider(m));
    }

    @Test void spheresExactlyTouchingFaceEdgeAndVertexOverlap() {
        for (CollideOracle o : oracles3()) {
            assertThat(o.checkOverlap(new double[] {1, 1, 1}, 1)).containsExactly(0);          // face, from above
            assertThat(o.checkOverlap(new double[] {1, 1, -2}, 2)).containsExactly(0);         // face, from below
            assertThat(o.checkOverlap(new double[] {2, -1, 0}, 1)).containsExactly(0);         // edge, in the plane
            assertThat(o.checkOverlap(new double[] {2, -3, 4}, 5)).containsExactly(0);         // edge, 3-4-5
            assertThat(o.checkOverlap(new double[] {-1, -2, -2}, 3)).containsExactly(0);       // vertex (0,0,0)
            assertThat(o.checkOverlap(new double[] {6, -1, 2}, 3)).containsExactly(0);         // vertex (4,0,0)
        }
    }

    @Test void spheresJustApartDoNotOverlap() {
        double below = Math.nextDown(1.0);
        for (CollideOracle o : oracles3()) {
            assertThat(o.checkOverlap(new double[] {1, 1, 1}, below)).isEmpty();
            assertThat(o.checkOverlap(new double[] {2, -1, 0}, below)).isEmpty();
            assertThat(o.checkOverlap(new double[] {-1, -2, -2}, Math.nextDown(3.0))).isEmpty();
        }
    }

    @Test void movingSphereHitsTheFaceFromEitherSide() {
        for (CollideOracle o : oracles3()) {
            Contact c = o.checkSweep(new double[] {1, 1, 5}, new double[] {0, 0, -8}, 1);
            assertContact(c, 0, 0.5, new double[] {1, 1, 0}, new double[] {0, 0, 1});
            c = o.checkSweep(new double[] {1, 1, -5}, new double[] {0, 0, 8}, 1);
            assertContact(c, 0, 0.5, new double[] {1, 1, 0}, new double[] {0, 0, -1});
        }
    }

    @Test void grazingAnEdgeOrAVertexExactlyIsAContactAtTheTangentMoment() {
        for (CollideOracle o : oracles3()) {
            // Across edge (0,0,0)-(4,0,0), at distance exactly 1 when z = 0: the cylinder's double root.
            Contact c = o.checkSweep(new double[] {2, -1, -3}, new double[] {0, 0, 6}, 1);
            assertContact(c, 0, 0.5, new double[] {2, 0, 0}, new double[] {0, -1, 0});
            // Slightly smaller misses. (Not one ulp smaller: r^2 |e|^2 then rounds back into 144 + 16.)
            assertThat(o.checkSweep(new double[] {2, -1, -3}, new double[] {0, 0, 6}, 1 - 0x1p-40).found()).isFalse();
            // Past vertex (0,0,0) at distance exactly 5 (3-4-5) when z = 0.
            c = o.checkSweep(new double[] {-3, -4, -3}, new double[] {0, 0, 6}, 5);
            assertContact(c, 0, 0.5, new double[] {0, 0, 0}, new double[] {-0.6, -0.8, 0});
            assertThat(o.checkSweep(new double[] {-3, -4, -3}, new double[] {0, 0, 6}, Math.nextDown(5.0)).found()).isFalse();
            // Along the edge's line, beside it: first touches the vertex (0,0,0), then slides along the edge.
            c = o.checkSweep(new double[] {-4, -1, 0}, new double[] {8, 0, 0}, 1);
            assertContact(c, 0, 0.5, new double[] {0, 0, 0}, new double[] {0, -1, 0});
        }
    }

    @Test void motionParallelToTheFace() {
        for (CollideOracle o : oracles3()) {
            // Above the face, out of reach: never touches.
            assertThat(o.checkSweep(new double[] {1, 1, 2}, new double[] {2, 0, 0}, 1).found()).isFalse();
            // Exactly at touching height, coming in over edge (0,4,0)-(0,0,0): touches when over that edge.
            Contact c = o.checkSweep(new double[] {-3, 1, 1}, new double[] {4, 0, 0}, 1);
            assertContact(c, 0, 0.75, new double[] {0, 1, 0}, new double[] {0, 0, 1});
        }
    }

    @Test void zeroLengthMotionAndAStartThatAlreadyTouches() {
        double[] still = {0, 0, 0};
        for (CollideOracle o : oracles3()) {
            assertContact(o.checkSweep(new double[] {1, 1, 1}, still, 1), 0, 0, new double[] {1, 1, 0}, new double[] {0, 0, 1});
            assertThat(o.checkSweep(new double[] {1, 1, 2}, still, 1).found()).isFalse();
            assertContact(o.checkSweep(new double[] {1, 1, 0.5}, new double[] {0, 0, 1}, 1), 0, 0,
                    new double[] {1, 1, 0}, new double[] {0, 0, 1});
        }
    }

    @Test void radiusZeroIsASegmentHitWithTheFaceNormalAgainstTheMotion() {
        for (CollideOracle o : oracles3()) {
            Contact c = o.checkSweep(new double[] {1, 1, 5}, new double[] {0, 0, -10}, 0);
            assertContact(c, 0, 0.5, new double[] {1, 1, 0}, new double[] {0, 0, 1});
            c = o.checkSweep(new double[] {1, 1, -5}, new double[] {0, 0, 10}, 0);
            assertContact(c, 0, 0.5, new double[] {1, 1, 0}, new double[] {0, 0, -1});
        }
    }

    @Test void spheresInsideAClosedBox() {
        List<double[]> tris = new ArrayList<>();
        TestScenes.addCube(tris, 0, 0, 0, 4);
        double[] v = new double[9 * tris.size()];
        for (int i = 0; i < tris.size(); i++) System.arraycopy(tris.get(i), 0, v, 9 * i, 9);
        TriangleMesh box = TestScenes.soup(v);
        for (CollideOracle o : CollideOracle.allBuilders(box, new MeshCollider(box))) {
            assertThat(o.checkOverlap(new double[] {2, 2, 2}, 1)).isEmpty();
            assertThat(o.checkOverlap(new double[] {2, 2, 2}, 2)).hasSize(12); // every face, both halves at the centre
            assertThat(o.checkOverlap(new double[] {1, 2, 2}, 1)).hasSize(2);  // face x = 0 at (0,2,2), on its diagonal
            assertThat(o.checkSweep(new double[] {1, 1, 1}, new double[] {8, 4, 2}, 1).t).isZero(); // already touching x, y, z = 0
            Contact c = o.checkSweep(new double[] {2, 2, 2}, new double[] {0, 0, 4}, 1);
            assertThat(c.t).isEqualTo(0.25);
            assertThat(c.normal).containsExactly(0, 0, -1);
            c = o.checkSweep(new double[] {2, 2, 2}, new double[] {8, 4, 2}, 1);
            assertThat(c.t).isEqualTo(0.125); // x reaches 3 first
            assertThat(c.normal).containsExactly(-1, 0, 0);
        }
    }

    // ---- 2-D ----

    private static List<CollideOracle> oracles2() {
        Scene2D s = new Scene2D(List.of(
                new Shape2D.Rect(0, 0, 4, 2),
                new Shape2D.Triangle(6, 0, 10, 0, 6, 4),
                new Shape2D.Segment(0, 6, 4, 6),
                new Shape2D.Point(8, 8)));
        return CollideOracle.allBuilders(s, new ShapeCollider(s));
    }

    @Test void circlesExactlyTouchingEachShapeKindOverlap() {
        for (CollideOracle o : oracles2()) {
            assertThat(o.checkOverlap(new double[] {2, 3}, 1)).containsExactly(0);     // rect's top edge
            assertThat(o.checkOverlap(new double[] {-3, -4}, 5)).containsExactly(0);   // rect's corner, 3-4-5
            assertThat(o.checkOverlap(new double[] {8, -1}, 1)).containsExactly(1);    // triangle's bottom edge
            assertThat(o.checkOverlap(new double[] {5, 6}, 1)).containsExactly(2);     // segment's end
            assertThat(o.checkOverlap(new double[] {2, 5}, 1)).containsExactly(2);     // segment's side
            assertThat(o.checkOverlap(new double[] {8, 9}, 1)).containsExactly(3);     // the point
            assertThat(o.checkOverlap(new double[] {8, 8}, 0)).containsExactly(3);     // radius 0 on the point
            assertThat(o.checkOverlap(new double[] {7, 1}, 0)).containsExactly(1);     // radius 0 inside the triangle
            assertThat(o.checkOverlap(new double[] {2, 3}, Math.nextDown(1.0))).isEmpty();
            assertThat(o.checkOverlap(new double[] {5, 6}, Math.nextDown(1.0))).isEmpty();
        }
    }

    @Test void movingCirclesHitGrazeAndStartInside() {
        for (CollideOracle o : oracles2()) {
            assertContact(o.checkSweep(new double[] {2, 10}, new double[] {0, -8}, 1), 2, 0.375,
                    new double[] {2, 6, 0}, new double[] {0, 1, 0});
            // Down the line x = 5: grazes the segment's end (4,6) at y = 6 first, exactly.
            assertContact(o.checkSweep(new double[] {5, 10}, new double[] {0, -8}, 1), 2, 0.5,
                    new double[] {4, 6, 0}, new double[] {1, 0, 0});
            // Starting below the segment, it grazes the triangle's corner (6,4) and the rect's (4,2):
            // the triangle first, at y = 4.
            assertContact(o.checkSweep(new double[] {5, 5}, new double[] {0, -4}, 1), 1, 0.25,
                    new double[] {6, 4, 0}, new double[] {-1, 0, 0});
            // Starting inside the filled rect: t = 0, normal against the motion.
            assertContact(o.checkSweep(new double[] {2, 1}, new double[] {1, 0}, 0.5), 0, 0,
                    new double[] {2, 1, 0}, new double[] {-1, 0, 0});
            // Radius 0: the segment's first hit.
            assertContact(o.checkSweep(new double[] {2, 10}, new double[] {0, -8}, 0), 2, 0.5,
                    new double[] {2, 6, 0}, new double[] {0, 1, 0});
            assertThat(o.checkSweep(new double[] {5, 10}, new double[] {0, 0}, 1).found()).isFalse();
        }
    }

    @Test void zeroAreaTrianglesAndRectsAreNeverTouchedAsRaysNeverHitThem() {
        TriangleMesh m = TestScenes.degenerateTriangles(); // three of zero area, then two ordinary
        MeshCollider c = new MeshCollider(m);
        double[] out = new double[3];
        for (int t = 0; t < 3; t++) {
            assertThat(c.closestPoint(t, new double[] {0.5, 0.5, 0.5}, out)).isInfinite();
            assertThat(c.firstContact(t, new double[] {-5, -5, -5}, new double[] {10, 10, 10}, 1, 1)).isInfinite();
        }
        assertThat(c.closestPoint(3, new double[] {0.5, 3, 0.5}, out)).isEqualTo(1); // the ordinary one, in y = 2
        Scene2D s = new Scene2D(List.of(new Shape2D.Triangle(0, 0, 1, 1, 2, 2), new Shape2D.Rect(0, 0, 0, 3),
                new Shape2D.Segment(1, 1, 1, 1)));
        ShapeCollider c2 = new ShapeCollider(s);
        assertThat(c2.closestPoint(0, new double[] {1, 1}, out)).isInfinite();
        assertThat(c2.closestPoint(1, new double[] {0, 1}, out)).isInfinite();
        assertThat(c2.firstContact(1, new double[] {-1, 1}, new double[] {2, 0}, 0.5, 1)).isInfinite();
        assertThat(c2.closestPoint(2, new double[] {1, 2}, out)).isEqualTo(1); // a zero-length segment is its point
    }

    private static void assertContact(Contact c, int primitive, double t, double[] point, double[] normal) {
        assertThat(c.found()).as("found " + c).isTrue();
        assertThat(c.primitive).as("primitive " + c).isEqualTo(primitive);
        assertThat(c.t).as("t " + c).isEqualTo(t);
        assertThat(c.point).as("point " + c).containsExactly(point);
        for (int a = 0; a < 3; a++) assertThat(c.normal[a]).as("normal " + c).isCloseTo(normal[a], within(1e-15));
    }
}
