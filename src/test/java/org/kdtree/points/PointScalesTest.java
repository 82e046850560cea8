package org.kdtree.points;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.kdtree.kdtree.SlidingMidpointBuilder;
import org.kdtree.shape.InvalidGeometryException;
import org.kdtree.shape.PointsKd;

/**
 * Squared distances overflow beyond coordinates of about 1e154 and underflow below extents of
 * about 1e-154: every distance would read infinity (or 0) and the neighbours would come back in
 * index order, a silent wrong answer. Within the supported range (geom.Tolerance) the answer is
 * the right one; beyond it the points are refused with the reason.
 */
class PointScalesTest {
    private static int nearestTo(double s) {
        PointsKd p = new PointsKd(2, new double[] {0, 0, 1 * s, 0, 3 * s, 0});
        NearestQuery q = new NearestQuery(PointTree.build(p, new SlidingMidpointBuilder()));
        int[] idx = new int[1];
        double[] dist = new double[1];
        q.nearest(new double[] {2.1 * s, 0}, 1, idx, dist);
        return idx[0];
    }

    @Test void theNearestPointIsRightAtTheEndsOfTheSupportedRange() {
        for (double s : new double[] {1, 1e99, 1e-99}) assertThat(nearestTo(s)).as("scale %s", s).isEqualTo(2);
    }

    @Test void pointsBeyondTheRangeAreRefusedNotAnsweredWrongly() {
        assertThatThrownBy(() -> nearestTo(1e200)).isInstanceOf(InvalidGeometryException.class)
                .hasMessageContaining("-1e100 .. 1e100");
        assertThatThrownBy(() -> nearestTo(1e-200)).isInstanceOf(InvalidGeometryException.class)
                .hasMessageContaining("smallest supported extent is 1e-100");
    }
}
