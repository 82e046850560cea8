package org.kdtree.geom;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import org.junit.jupiter.api.Test;

class PolygonClipperTest {
    private final PolygonClipper clipper = new PolygonClipper(3);

    @Test void aTriangleCutByAPlaneKeepsTheExactBoundsOfThePartInside() {
        double[] tri = {0, 0, 0, 4, 0, 0, 0, 4, 0};
        Box b = clipper.clip(tri, 3, Box.of3(1, -1, -1, 5, 5, 1), new Box(3));
        assertTightAndConservative(b, Box.of3(1, 0, 0, 4, 3, 0));
    }

    @Test void aTriangleOutsideTheBoxGivesAnEmptyBox() {
        double[] tri = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        assertThat(clipper.clip(tri, 3, Box.of3(2, 2, 2, 3, 3, 3), new Box(3)).isEmpty()).isTrue();
        // the box's corner region misses the triangle although the bounding boxes overlap
        assertThat(clipper.clip(tri, 3, Box.of3(0.6, 0.6, -1, 1, 1, 1), new Box(3)).isEmpty()).isTrue();
    }

    @Test void aSegmentIsClippedToo() {
        PolygonClipper c2 = new PolygonClipper(2);
        Box b = c2.clip(new double[] {0, 0, 10, 5}, 2, Box.of2(2, 0, 4, 10), new Box(2));
        assertTightAndConservative(b, Box.of2(2, 1, 4, 2));
    }

    /**
     * Bounds on a box face or a vertex coordinate are exact; computed ones may be padded outward by a
     * few units in the last place, never inward.
     */
    private static void assertTightAndConservative(Box actual, Box exact) {
        for (int a = 0; a < exact.dimension(); a++) {
            assertThat(actual.min(a)).isLessThanOrEqualTo(exact.min(a)).isCloseTo(exact.min(a), org.assertj.core.data.Offset.offset(1e-14));
            assertThat(actual.max(a)).isGreaterThanOrEqualTo(exact.max(a)).isCloseTo(exact.max(a), org.assertj.core.data.Offset.offset(1e-14));
        }
    }

    @Test void boundsOnFacesAndVerticesAreExact() {
        double[] tri = {0, 0, 0, 4, 0, 0, 0, 4, 0};
        Box b = clipper.clip(tri, 3, Box.of3(1, -1, -1, 5, 5, 1), new Box(3));
        assertThat(b.min(0)).as("the clipping face").isEqualTo(1);
        assertThat(b.max(0)).as("a vertex").isEqualTo(4);
        assertThat(b.min(1)).as("a vertex").isZero();
    }

    /** The clipped bounds contain every point of the triangle that lies in the box. */
    @Property(tries = 200)
    void clippedBoundsAreConservative(@ForAll long seed) {
        Random r = new Random(seed);
        double[] tri = new double[9];
        for (int i = 0; i < 9; i++) tri[i] = r.nextDouble() * 2 - 1;
        double[] lo = new double[3], hi = new double[3];
        for (int a = 0; a < 3; a++) {
            double x = r.nextDouble() * 2 - 1, y = r.nextDouble() * 2 - 1;
            lo[a] = Math.min(x, y);
            hi[a] = Math.max(x, y);
        }
        Box box = new Box(lo, hi);
        Box clip = clipper.clip(tri, 3, box, new Box(3));
        for (int s = 0; s < 2000; s++) {
            double u = r.nextDouble(), v = r.nextDouble();
            if (u + v > 1) { u = 1 - u; v = 1 - v; }
            double[] p = new double[3];
            for (int a = 0; a < 3; a++) p[a] = (1 - u - v) * tri[a] + u * tri[3 + a] + v * tri[6 + a];
            if (box.contains(p)) assertThat(clip.contains(p)).as("point %s inside box", java.util.Arrays.toString(p)).isTrue();
        }
    }
}
