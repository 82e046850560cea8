package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.BitSet;
import org.junit.jupiter.api.Test;
import org.kdtree.generate.Meshes;
import org.kdtree.generate.Shapes;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.TriangleMesh;

/** Binned SAH: a valid tree whose expected cost is close to, and never far below, the exact one. */
class BinnedSahTest {
    private static final TriangleMesh SPHERE = Meshes.surface(30, 50, 21);

    @Test void binnedTreeHoldsEveryPrimitiveAndCostsLittleMoreThanExact() {
        double exact = new SahBuilder().build(SPHERE).stats().expectedCost();
        for (int bins : new int[] {8, 32, 256}) {
            KdTree t = new SahBuilder().algorithm(SahBuilder.Algorithm.BINNED).bins(bins).build(SPHERE);
            assertEveryPrimitiveReferenced(t, SPHERE);
            assertThat(t.stats().expectedCost()).as("B = %d", bins).isBetween(0.95 * exact, 1.1 * exact);
            KdTree pure = new SahBuilder().algorithm(SahBuilder.Algorithm.BINNED).bins(bins).exactBelow(0).build(SPHERE);
            assertEveryPrimitiveReferenced(pure, SPHERE);
            assertThat(pure.stats().expectedCost()).as("pure, B = %d", bins).isBetween(0.95 * exact, 1.4 * exact);
        }
    }

    @Test void binnedWorksIn2DAndOnDegenerateScenes() {
        for (Primitives p : new Primitives[] {Shapes.aligned(200, 22), Meshes.planarAndDegenerate(23)}) {
            KdTree t = new SahBuilder().algorithm(SahBuilder.Algorithm.BINNED).bins(16).build(p);
            assertEveryPrimitiveReferenced(t, p);
            assertThat(t.nodeCount()).isGreaterThan(1);
        }
    }

    @Test void settingsAreCheckedAndReported() {
        assertThatThrownBy(() -> new SahBuilder().bins(1)).isInstanceOf(IllegalArgumentException.class);
        assertThat(new SahBuilder().algorithm(SahBuilder.Algorithm.BINNED).bins(64).describeSettings())
                .contains("algorithm=binned", "bins=64");
        assertThat(SahBuilder.Algorithm.BINNED.exact()).isFalse();
        assertThat(SahBuilder.Algorithm.EVENT.exact()).isTrue();
    }

    static void assertEveryPrimitiveReferenced(KdTree t, Primitives p) {
        BitSet seen = new BitSet();
        for (int r : t.refArray()) seen.set(r);
        assertThat(seen.cardinality()).isEqualTo(p.size());
    }
}
