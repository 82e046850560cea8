package org.kdtree.shape;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.kdtree.geom.Box;

class TriangleMeshTest {
    @Test void nonFiniteCoordinatesAreRejectedNamingTheTriangleAndVertex() {
        double[] v = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, Double.POSITIVE_INFINITY, 0};
        assertThatThrownBy(() -> new TriangleMesh(v, new int[] {0, 1, 2, 0, 1, 3}))
                .isInstanceOf(InvalidGeometryException.class)
                .hasMessage("triangle 1 has a non-finite coordinate (Infinity) at vertex 3");
    }

    @Test void indicesOutOfRangeAreRejected() {
        assertThatThrownBy(() -> new TriangleMesh(new double[9], new int[] {0, 1, 5}))
                .hasMessage("triangle 0 refers to vertex 5 of 3");
    }

    @Test void boundsAndClipping() {
        TriangleMesh m = new TriangleMesh(new double[] {0, 0, 0, 2, 0, 0, 0, 2, 2}, new int[] {0, 1, 2});
        Box b = new Box(3);
        m.bounds(0, b);
        assertThat(b).isEqualTo(Box.of3(0, 0, 0, 2, 2, 2));
        m.clip(0, Box.of3(-1, -1, -1, 3, 3, 1), b);
        assertThat(b.max(2)).isEqualTo(1);
        assertThat(b.max(1)).isCloseTo(1, org.assertj.core.data.Offset.offset(1e-14));
    }

    @Test void shapes2DRejectNaNNamingTheShape() {
        assertThatThrownBy(() -> new Scene2D(java.util.List.of(new Shape2D.Point(0, 0), new Shape2D.Segment(0, 0, Double.NaN, 1))))
                .hasMessage("segment 1 has a non-finite coordinate (NaN)");
    }
}
