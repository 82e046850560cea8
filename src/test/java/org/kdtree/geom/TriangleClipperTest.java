package org.kdtree.geom;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The specialised triangle clipper must agree with the generic one bit for bit: the SAH trees depend on it. */
class TriangleClipperTest {
    private final PolygonClipper generic = new PolygonClipper(3);
    private final TriangleClipper fast = new TriangleClipper();

    @Test void randomTrianglesAndBoxesGiveBitIdenticalBounds() {
        Random r = new Random(42);
        for (int i = 0; i < 200_000; i++) {
            // coordinates on a coarse grid half the time, so that vertices fall exactly on faces
            boolean snapped = i % 2 == 0;
            double[] v = new double[9];
            for (int c = 0; c < 9; c++) v[c] = coordinate(r, snapped);
            if (i % 7 == 0) v[2] = v[5] = v[8];             // flat in z
            if (i % 11 == 0) System.arraycopy(v, 0, v, 3, 3); // degenerate: two equal corners
            double[] lo = new double[3], hi = new double[3];
            for (int a = 0; a < 3; a++) {
                double x = coordinate(r, snapped), y = coordinate(r, snapped);
                lo[a] = Math.min(x, y);
                hi[a] = i % 13 == 0 && a == 1 ? lo[a] : Math.max(x, y); // flat boxes too
            }
            Box box = new Box(lo, hi);
            Box expected = generic.clip(v, 3, box, new Box(3));
            Box actual = fast.clip(v, 0, 1, 2, box, new Box(3));
            assertSameBits(actual, expected, i);
        }
    }

    @Test void clipSplitAgreesWithClippingEachHalfUpToThePadding() {
        Random r = new Random(7);
        int nonEmpty = 0;
        for (int i = 0; i < 100_000; i++) {
            boolean snapped = i % 2 == 0;
            double[] v = new double[9];
            for (int c = 0; c < 9; c++) v[c] = coordinate(r, snapped);
            if (i % 7 == 0) v[2] = v[5] = v[8];
            double[] lo = new double[3], hi = new double[3];
            for (int a = 0; a < 3; a++) {
                // No flat boxes: clipping a triangle that crosses a zero-thickness slab is
                // ill-conditioned for any clipper, and never happens in a build (a voxel is flat only
                // when every primitive lies in that plane).
                double x = coordinate(r, snapped), y = coordinate(r, snapped);
                if (x == y) y = x + 1;
                lo[a] = Math.min(x, y);
                hi[a] = Math.max(x, y);
            }
            Box box = new Box(lo, hi);
            int axis = i % 3;
            double xi = snapped ? Math.rint((lo[axis] + hi[axis]) / 2) : lo[axis] + r.nextDouble() * (hi[axis] - lo[axis]);
            xi = Math.min(Math.max(xi, lo[axis]), hi[axis]);
            Box left = new Box(3), right = new Box(3);
            fast.clipSplit(v, 0, 1, 2, box, axis, xi, left, right);
            nonEmpty += assertClose(left, generic.clip(v, 3, box.lowerPart(axis, xi), new Box(3)), i);
            nonEmpty += assertClose(right, generic.clip(v, 3, box.upperPart(axis, xi), new Box(3)), i);
        }
        assertThat(nonEmpty).as("cases where a half holds part of the triangle").isGreaterThan(30_000);
    }

    /**
     * Both results are padded by about 4.5 ulps of the triangle's coordinates, so they may differ
     * by that much. Where the triangle only touches a half (along a face or an edge of it), both
     * see a sliver or nothing, and which part of the contact each finds depends on rounding.
     */
    private static int assertClose(Box actual, Box expected, int caseNumber) {
        if (sliver(expected) || sliver(actual)) {
            assertThat(sliver(actual)).as("case %d: the other clip sees only a sliver", caseNumber).isTrue();
            assertThat(sliver(expected)).as("case %d: the other clip sees only a sliver", caseNumber).isTrue();
            return 0;
        }
        for (int a = 0; a < 3; a++) {
            assertThat(actual.min(a)).as("case %d: min %d", caseNumber, a).isCloseTo(expected.min(a), within(1e-13));
            assertThat(actual.max(a)).as("case %d: max %d", caseNumber, a).isCloseTo(expected.max(a), within(1e-13));
        }
        return 1;
    }

    private static boolean sliver(Box b) {
        return b.isEmpty() || flat(b);
    }

    private static boolean flat(Box b) {
        for (int a = 0; a < 3; a++) if (b.max(a) - b.min(a) < 1e-12) return true;
        return false;
    }

    @Test void cornersAreReadThroughTheIndexArrayOfAMesh() {
        double[] vertices = {9, 9, 9, 0, 0, 0, 4, 0, 0, 0, 4, 0};
        Box box = Box.of3(1, -1, -1, 5, 5, 1);
        Box b = fast.clip(vertices, 1, 2, 3, box, new Box(3));
        assertSameBits(b, generic.clip(new double[] {0, 0, 0, 4, 0, 0, 0, 4, 0}, 3, box, new Box(3)), 0);
        assertThat(b.min(0)).isEqualTo(1);
        assertThat(b.max(1)).isGreaterThanOrEqualTo(3);
    }

    private static double coordinate(Random r, boolean snapped) {
        return snapped ? r.nextInt(9) - 4 : (r.nextDouble() - 0.5) * 8;
    }

    private static void assertSameBits(Box actual, Box expected, int caseNumber) {
        assertThat(actual.isEmpty()).as("case %d: empty", caseNumber).isEqualTo(expected.isEmpty());
        if (expected.isEmpty()) return;
        for (int a = 0; a < 3; a++) {
            assertThat(Double.doubleToRawLongBits(actual.min(a))).as("case %d: min %d", caseNumber, a)
                    .isEqualTo(Double.doubleToRawLongBits(expected.min(a)));
            assertThat(Double.doubleToRawLongBits(actual.max(a))).as("case %d: max %d", caseNumber, a)
                    .isEqualTo(Double.doubleToRawLongBits(expected.max(a)));
        }
    }
}
