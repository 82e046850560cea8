package org.kdtree.collide;

import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.kdtree.kdtree.SahBuilder;
import org.kdtree.shape.InvalidGeometryException;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;

/** Beyond 1e100 squared distances overflow: queries and scenes out there are refused with the reason, not answered wrongly. */
class QueryRangeTest {
    private final Scene2D scene = new Scene2D(List.of(new Shape2D.Rect(0, 0, 1, 1), new Shape2D.Point(3, 3)));
    private final OverlapQuery overlap = new OverlapQuery(new SahBuilder().build(scene), new ShapeCollider(scene));
    private final SweepQuery sweep = new SweepQuery(new SahBuilder().build(scene), new ShapeCollider(scene));

    @Test void centresMotionsAndRadiiBeyondTheRangeAreRefused() {
        int[] out = new int[4];
        assertThatThrownBy(() -> overlap.overlapping(new double[] {1e200, 0}, 1, out)).hasMessageContaining("-1e100 .. 1e100");
        assertThatThrownBy(() -> overlap.overlapping(new double[] {0, 0}, 1e200, out)).hasMessage("radius must be between 0 and 1e100, got 1.0E200");
        assertThatThrownBy(() -> sweep.firstContact(new double[] {0, 0}, new double[] {1e200, 0}, 1, new Contact()))
                .hasMessageContaining("-1e100 .. 1e100");
    }

    @Test void aSceneBeyondTheRangeIsRefused() {
        assertThatThrownBy(() -> new Scene2D(List.of(new Shape2D.Point(1e200, 0)))).isInstanceOf(InvalidGeometryException.class)
                .hasMessageContaining("the supported range is -1e100 .. 1e100");
    }
}
