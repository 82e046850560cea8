package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class SplitOutcomeTest {
    @Test void aSplitThatSendsEveryPrimitiveToBothChildrenOrToNeitherSeparatesNothing() {
        assertThat(SplitOutcome.of(5, 5, 5, 1000)).isEqualTo(SplitOutcome.SEPARATES_NOTHING);
        // zero-area primitives whose clipped parts vanish on both sides: a split would lose them,
        // and the children's budget shares would divide by zero
        assertThat(SplitOutcome.of(3, 0, 0, 1000)).isEqualTo(SplitOutcome.SEPARATES_NOTHING);
        assertThat(SplitOutcome.of(5, 5, 0, 1000)).isEqualTo(SplitOutcome.SPLIT);
        assertThat(SplitOutcome.of(5, 2, 3, 1000)).isEqualTo(SplitOutcome.SPLIT);
    }

    @Test void aSplitOverItsNodesBudgetMakesALeaf() {
        assertThat(SplitOutcome.of(5, 5, 4, 8)).isEqualTo(SplitOutcome.OVER_BUDGET);
        assertThat(SplitOutcome.of(5, 4, 4, 8)).isEqualTo(SplitOutcome.SPLIT);
    }

    @Test void anEmptyNodeIsNeverALeafForSeparatingNothing() {
        assertThat(SplitOutcome.of(0, 0, 0, 8)).isEqualTo(SplitOutcome.SPLIT);
    }
}
