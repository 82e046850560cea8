package org.kdtree.tradeoff;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kdtree.kdtree.SlidingMidpointBuilder;
import org.kdtree.points.NearestQuery;
import org.kdtree.points.PointTree;
import org.kdtree.shape.PointsKd;

/** Recall against the brute-force oracle: exact where it must be, bounded, and growing with the budget. */
class NeighbourStudyTest {
    private static NeighbourStudy study(GeneratedPoints kind, int n, int dim, int k) {
        PointTree tree = PointTree.build(kind.points(n, dim, 7), new SlidingMidpointBuilder());
        return new NeighbourStudy(tree, kind.queries(60, dim, 7), k, 1);
    }

    @Test void theExactSearchesHaveRecallOne() {
        NeighbourStudy s = study(GeneratedPoints.UNIFORM, 2000, 6, 10);
        assertThat(s.exact().recall()).isEqualTo(1.0);
        assertThat(s.budget(NearestQuery.UNLIMITED).recall()).isEqualTo(1.0);
        assertThat(s.epsilon(0).recall()).isEqualTo(1.0);
        assertThat(s.bruteForce().recall()).isEqualTo(1.0);
        assertThat(s.bruteForce().speedUp()).isEqualTo(1.0);
    }

    /**
     * With a larger budget best-bin-first scans the same leaves in the same order and then more,
     * so per query it keeps at least as many true neighbours: recall cannot fall.
     */
    @Test void recallIsAFractionThatGrowsWithTheBudget() {
        for (GeneratedPoints kind : GeneratedPoints.values()) {
            NeighbourStudy s = study(kind, 3000, 8, 10);
            List<Double> recalls = new ArrayList<>();
            for (int budget : new int[] {1, 2, 4, 8, 16, 32, 64, NearestQuery.UNLIMITED}) recalls.add(s.budget(budget).recall());
            assertThat(recalls).as(kind.label()).allSatisfy(r -> assertThat(r).isBetween(0.0, 1.0)).isSorted();
            assertThat(recalls.get(0)).as(kind.label() + ": one leaf of 8-D data misses some").isLessThan(1.0);
            assertThat(recalls.get(recalls.size() - 1)).isEqualTo(1.0);
        }
    }

    @Test void aPointAsNearAsTheTrueKthCountsAsCorrect() {
        // a grid: the query (1, 1) has four neighbours at distance 1; any two of them are a right answer
        double[] c = {1, 0, 0, 1, 2, 1, 1, 2, 5, 5};
        PointTree tree = PointTree.build(new PointsKd(2, c), new SlidingMidpointBuilder());
        NeighbourStudy s = new NeighbourStudy(tree, new PointsKd(2, new double[] {1, 1}), 2, 1);
        for (int budget = 1; budget <= 4; budget++) assertThat(s.budget(budget).recall()).isEqualTo(1.0);
    }

    @Test void theCsvHasOneRowPerMeasurementWithItsColumns() {
        NeighbourStudy s = study(GeneratedPoints.CLUSTERED, 500, 3, 4);
        List<NeighbourResult> results = List.of(s.bruteForce(), s.exact(), s.budget(1), s.budget(8), s.epsilon(0.5));
        List<String> lines = NeighbourStudy.csv(results).lines().toList();
        assertThat(lines.get(0)).isEqualTo("search,setting,recall,queries_per_s,leaves_per_query,speed_up");
        assertThat(lines).hasSize(6);
        assertThat(lines.subList(1, 6)).allSatisfy(l -> assertThat(l.split(",", -1)).hasSize(6));
        assertThat(lines.get(3)).startsWith("best-bin-first,1,");
        assertThat(lines.get(5)).startsWith("epsilon,0.5,");
        assertThat(lines.get(1)).startsWith("brute force,,1.000000,");
    }

    @Test void generatedSetsAreTheSameForASeed() {
        PointsKd a = GeneratedPoints.CLUSTERED.points(100, 5, 3), b = GeneratedPoints.CLUSTERED.points(100, 5, 3);
        PointsKd q = GeneratedPoints.CLUSTERED.queries(100, 5, 3);
        for (int i = 0; i < 100; i++)
            for (int d = 0; d < 5; d++) {
                assertThat(a.coord(i, d)).isEqualTo(b.coord(i, d));
                assertThat(q.coord(i, d)).isNotEqualTo(a.coord(i, d));
            }
        assertThatThrownBy(() -> GeneratedPoints.named("gaussian"))
                .hasMessage("the kind of generated points must be uniform or clustered, got 'gaussian'");
    }
}
