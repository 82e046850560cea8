package org.kdtree.traverse;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.kdtree.traverse.TraversalListener.Visit;

/** Algorithm 2's decision at an interior node, case by case (Havran's list). */
class DecideTest {
    @Test void theThreeCasesOfTheTalk() {
        assertThat(Traverser.decide(5, 1, 3)).isEqualTo(Visit.NEAR);
        assertThat(Traverser.decide(0.5, 1, 3)).isEqualTo(Visit.FAR);
        assertThat(Traverser.decide(2, 1, 3)).isEqualTo(Visit.BOTH);
    }

    @Test void tiesVisitBothChildren() {
        assertThat(Traverser.decide(1, 1, 3)).isEqualTo(Visit.BOTH);
        assertThat(Traverser.decide(3, 1, 3)).isEqualTo(Visit.BOTH);
        assertThat(Traverser.decide(Math.nextUp(3.0), 1, 3)).as("within rounding").isEqualTo(Visit.BOTH);
        assertThat(Traverser.decide(0, 0, 0)).as("origin on the plane, empty-length interval").isEqualTo(Visit.BOTH);
        assertThat(Traverser.decide(-0.0, 0, 3)).isEqualTo(Visit.BOTH);
    }

    @Test void raysParallelToThePlaneVisitOneChildRaysInItVisitBoth() {
        assertThat(Traverser.decide(Double.POSITIVE_INFINITY, 1, 3)).isEqualTo(Visit.NEAR);
        assertThat(Traverser.decide(Double.NEGATIVE_INFINITY, 1, 3)).isEqualTo(Visit.FAR);
        assertThat(Traverser.decide(0.0 * Double.POSITIVE_INFINITY, 1, 3)).isEqualTo(Visit.BOTH_IN_PLANE);
    }
}
