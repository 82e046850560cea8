package org.kdtree.tree;

import static org.assertj.core.api.Assertions.assertThat;

import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.Provide;
import org.junit.jupiter.api.Test;
import org.kdtree.geom.Box;

/** The grid of stored split positions: nearest really is nearest, on the grid, inside the voxel, at every scale. */
class SplitGridTest {
    /** A root axis [min, min + extent] at scales 1e-100 .. 1e100 and offsets up to 1e8 extents, and a voxel in it. */
    record Case(double min, double max, double lo, double hi, double x) {
    }

    @Provide Arbitrary<Case> cases() {
        Arbitrary<Double> scale = Arbitraries.integers().between(-100, 100).map(e -> Math.pow(10, e));
        Arbitrary<Double> offset = Arbitraries.of(0.0, 1.0, -1.0, 1e3, -1e6, 1e8, 0.5);
        Arbitrary<Double> f = Arbitraries.doubles().between(0, 1);
        return Combinators.combine(scale, offset, f, f, f).as((s, o, a, b, c) -> {
            double min = o * s, max = min + s, extent = max - min;
            double lo = min + Math.min(a, b) * extent, hi = Math.min(max, min + Math.max(a, b) * extent);
            lo = Math.max(min, Math.min(lo, hi));
            double x = Math.min(hi, Math.max(lo, lo + c * (hi - lo)));
            return new Case(min, max, lo, hi, x);
        });
    }

    @Property(tries = 3000)
    void nearestIsOnTheGridInsideTheVoxelAndNoOtherGridPositionThereIsCloser(@ForAll("cases") Case c) {
        SplitGrid grid = new SplitGrid(new Box(new double[] {c.min()}, new double[] {c.max()}));
        double p = grid.nearest(0, c.x(), c.lo(), c.hi());
        if (p != p) { // none in the voxel: then its ends' neighbours on the grid lie outside it
            double below = grid.nearest(0, c.lo(), Double.NEGATIVE_INFINITY, c.lo());
            assertThat(below).isLessThan(c.lo());
            return;
        }
        assertThat(p).isBetween(c.lo(), c.hi());
        float u = grid.code(0, p);
        assertThat(grid.position(0, u)).isEqualTo(p);
        for (float v : new float[] {Math.nextUp(u), Math.nextDown(u)}) {
            double q = grid.position(0, v);
            if (q >= c.lo() && q <= c.hi()) assertThat(Math.abs(q - c.x())).isGreaterThanOrEqualTo(Math.abs(p - c.x()));
        }
    }

    @Test void theGridIsAsFineFarFromTheOriginAsNearIt() {
        for (double offset : new double[] {0, 1e6, -1e12, 1e90}) {
            double scale = offset == 1e90 ? 1e88 : 1;
            SplitGrid grid = new SplitGrid(new Box(new double[] {offset}, new double[] {offset + scale}));
            double x = offset + 0.7 * scale;
            double p = grid.nearest(0, x, offset, offset + scale);
            assertThat(Math.abs(p - x)).as("offset %s", offset).isLessThanOrEqualTo(scale * 0x1p-23 + Math.ulp(x));
        }
    }

    @Test void nearTheOriginRoundCoordinatesAreExactPlanes() {
        SplitGrid grid = new SplitGrid(Box.of2(0, -3, 10, 2.5));
        assertThat(grid.nearest(0, 6, 0, 10)).isEqualTo(6);
        assertThat(grid.nearest(0, 0.1, 0, 10)).isEqualTo((float) 0.1);
        assertThat(grid.nearest(1, -2.75, -3, 2.5)).isEqualTo(-2.75);
        assertThat(grid.code(1, -3)).isEqualTo(-0.75f);
    }

    @Test void aFlatAxisHasOnePosition() {
        SplitGrid grid = new SplitGrid(Box.of2(-2, 5, 3, 5));
        assertThat(grid.nearest(1, 5, 5, 5)).isEqualTo(5);
        assertThat(grid.atOrBelow(1, 5)).isEqualTo(5);
    }
}
