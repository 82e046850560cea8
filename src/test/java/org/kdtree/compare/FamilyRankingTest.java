package org.kdtree.compare;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Issue 48's test of the distance as an index: over five families of 2-D and 5-D point sets,
 * several noisy instances of each, every one shifted and scaled at random, the instance nearest
 * to each query (the query left out) is of the query's family for at least 90 % of the queries.
 */
class FamilyRankingTest {
    private static final int INSTANCES = 6, N = 2000;

    @ParameterizedTest(name = "{0}-D")
    @ValueSource(ints = {2, 5})
    void theNearestSetIsOfTheSameFamily(int k) {
        List<TreeSignature> signatures = new ArrayList<>();
        List<Integer> family = new ArrayList<>();
        for (int f = 0; f < Families.NAMES.size(); f++)
            for (int i = 0; i < INSTANCES; i++) {
                long seed = 1000L * f + i + 100_000L * k;
                int n = N / 2 + (int) Math.floorMod(seed * 7919, N);   // 1,000 to 3,000 points: the term of depths sees the size
                signatures.add(Families.signature(Families.moved(Families.instance(f, n, k, seed), ~seed)));
                family.add(f);
            }
        int right = 0;
        List<String> wrong = new ArrayList<>();
        for (int q = 0; q < signatures.size(); q++) {
            int best = -1;
            double bestDistance = Double.POSITIVE_INFINITY;
            for (int j = 0; j < signatures.size(); j++) {
                if (j == q) continue;
                double d = TreeDistance.of(signatures.get(q), signatures.get(j));
                if (d < bestDistance) { bestDistance = d; best = j; }
            }
            if (family.get(best).equals(family.get(q))) right++;
            else wrong.add(Families.NAMES.get(family.get(q)) + " #" + q + " -> " + Families.NAMES.get(family.get(best))
                    + " at " + bestDistance);
        }
        System.out.printf("%d-D: %d of %d queries find their family first; misses: %s%n", k, right, signatures.size(), wrong);
        assertThat(right).as("queries whose nearest set is of their family (misses: %s)", wrong)
                .isGreaterThanOrEqualTo((int) Math.ceil(0.9 * signatures.size()));
    }
}
