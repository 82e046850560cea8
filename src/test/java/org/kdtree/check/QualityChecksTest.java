package org.kdtree.check;

import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.kdtree.SahBuilder;
import org.kdtree.kdtree.SlidingMidpointBuilder;

/** The quality tier passes the SAH and flags the useless builders the issue found passing the contract. */
class QualityChecksTest {
    /** Splits every node at the upper face of its voxel: valid, and useless. */
    static final class PlanesOnTheFace extends KdTreeBuilder {
        @Override public String name() { return "planes-on-the-face"; }
        @Override protected boolean terminate(BuildContext c, BuildNode n) { return n.size() <= 2; }
        @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) {
            int axis = n.depth() % n.dimension();
            return new SplitPlane(axis, n.voxel().max(axis));
        }
    }

    private static ContractCase quality(String prefix) {
        return QualityChecks.cases().stream().filter(c -> c.name().startsWith(prefix)).findFirst().orElseThrow();
    }

    @Test void theSahPassesEveryQualityCheck() {
        for (ContractCase c : QualityChecks.cases()) c.run(SahBuilder::new);
    }

    @Test void planesOnTheVoxelsFaceSeparateNothing() {
        assertThatThrownBy(() -> quality("planes separate").run(PlanesOnTheFace::new))
                .isInstanceOf(ContractViolation.class)
                .hasMessageContaining("planes-on-the-face: on talk-figures")
                .hasMessageContaining("split planes separate nothing");
        assertThatThrownBy(() -> quality("expected cost").run(PlanesOnTheFace::new))
                .hasMessageContaining("times the median-plane builder's");
    }

    @Test void aBuilderThatNeverStopsFailsAtOnce() {
        assertThatThrownBy(() -> quality("leaves stop").run(ContractCatchesBrokenBuildersTest.NeverStops::new))
                .isInstanceOf(ContractViolation.class)
                .hasMessageContaining("never-stops never stops");
    }

    @Test void costsAboveTheMedianPlanesAreFlagged() {
        assertThatThrownBy(() -> quality("expected cost").run(SlidingMidpointBuilder::new))
                .hasMessageContaining("sliding-midpoint: on talk-figures, the tree's expected SAH cost is 120.00");
    }
}
