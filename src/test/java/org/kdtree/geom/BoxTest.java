package org.kdtree.geom;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class BoxTest {
    @Test void surfaceAreaIsPerimeterIn2DAndAreaIn3D() {
        assertThat(Box.of2(0, 0, 3, 2).surfaceArea()).isEqualTo(10);
        assertThat(Box.of3(0, 0, 0, 1, 2, 3).surfaceArea()).isEqualTo(22);
        assertThat(new Box(new double[] {0}, new double[] {5}).surfaceArea()).isEqualTo(2);
        // 4-D unit hypercube: 8 cubic faces of measure 1
        assertThat(new Box(new double[4], new double[] {1, 1, 1, 1}).surfaceArea()).isEqualTo(8);
    }

    @Test void flatBoxesKeepAPositiveArea() {
        Box flat = Box.of3(0, 0, 1, 2, 3, 1);
        assertThat(flat.surfaceArea()).isEqualTo(12);
        assertThat(flat.isEmpty()).isFalse();
        assertThat(flat.volume()).isZero();
    }

    @Test void emptyBoxesHaveNoArea() {
        Box e = new Box(3);
        assertThat(e.isEmpty()).isTrue();
        assertThat(e.surfaceArea()).isZero();
    }

    @Test void cuttingAVoxelGivesTwoChildrenThatTileIt() {
        Box v = Box.of2(0, 0, 4, 2);
        Box l = v.lowerPart(0, 1), r = v.upperPart(0, 1);
        assertThat(l).isEqualTo(Box.of2(0, 0, 1, 2));
        assertThat(r).isEqualTo(Box.of2(1, 0, 4, 2));
        assertThat(l.volume() + r.volume()).isEqualTo(v.volume());
    }
}
