package org.kdtree.accel;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.kdtree.geom.Ray;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;

class Shape2DIntersectorTest {
    private static Hit shoot(Shape2D s, double ox, double oy, double dx, double dy) {
        Hit h = new Hit();
        new Shape2DIntersector(new Scene2D(List.of(s))).intersect(0, new Ray(2).set(ox, oy, dx, dy), 0,
                Double.POSITIVE_INFINITY, h);
        return h;
    }

    @Test void segmentsAreHitAtTheirEndsAndAlongThemselves() {
        Shape2D seg = new Shape2D.Segment(0, 0, 2, 0);
        assertThat(shoot(seg, 1, 1, 0, -1).t).isEqualTo(1.0);
        assertThat(shoot(seg, 0, 1, -0.0, -1).t).isEqualTo(1.0);
        assertThat(shoot(seg, 2, -3, 0.0, 1).t).isEqualTo(3.0);
        assertThat(shoot(seg, 2.0000000000000004, -3, 0.0, 1).found()).isFalse();
        assertThat(shoot(seg, -1, 0, 1, 0.0).t).as("along the segment").isEqualTo(1.0);
        assertThat(shoot(seg, 3, 0, -1, -0.0).t).as("along, backwards").isEqualTo(1.0);
        assertThat(shoot(seg, 1, 0, 1, 0).t).as("starting on it").isEqualTo(0.0);
        assertThat(shoot(seg, -1, 1, 1, 0).found()).as("parallel").isFalse();
    }

    @Test void filledRectanglesAndTriangles() {
        Shape2D rect = new Shape2D.Rect(0, 0, 2, 1);
        assertThat(shoot(rect, -1, 0.5, 1, 0).t).isEqualTo(1.0);
        assertThat(shoot(rect, 1, 0.5, 1, 0).t).as("from inside").isEqualTo(0.0);
        assertThat(shoot(rect, -1, 1, 1, 0.0).t).as("grazing the top edge").isEqualTo(1.0);
        assertThat(shoot(rect, -1, -1, 1, 1).t).as("through a corner").isEqualTo(1.0);
        assertThat(shoot(rect, -1, 1.5, 1, 0).found()).isFalse();
        Shape2D tri = new Shape2D.Triangle(0, 0, 2, 0, 0, 2);
        assertThat(shoot(tri, 0.5, 0.5, 1, 0).t).as("from inside").isEqualTo(0.0);
        assertThat(shoot(tri, 3, 3, -1, -1).t).isEqualTo(2.0);
        assertThat(shoot(tri, 2, 5, -0.0, -1).t).as("through a vertex").isEqualTo(5.0);
        assertThat(shoot(tri, 3, 2.5, -1, 0).found()).isFalse();
    }

    @Test void degenerateShapesAreNeverHitAndPointsOnlyExactly() {
        assertThat(shoot(new Shape2D.Rect(0, 0, 0, 1), -1, 0.5, 1, 0).found()).isFalse();
        assertThat(shoot(new Shape2D.Triangle(0, 0, 1, 1, 2, 2), -1, 1, 1, 0).found()).isFalse();
        Shape2D p = new Shape2D.Point(1, 1);
        assertThat(shoot(p, 0, 0, 1, 1).t).isEqualTo(1.0);
        assertThat(shoot(p, 1, 0, 0.0, 1).t).isEqualTo(1.0);
        assertThat(shoot(p, 0, 0, 1, 1.0000000000000002).found()).isFalse();
    }
}
