package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import java.util.Comparator;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The one event sort gives the order of a stable sort of the doubles, codes included: on
 * positions closer than a float's ulp, equal ones, both zeros, and values beyond a float's range.
 * The radix path (more than {@link EventSort#INSERTION} events) puts -0.0 before 0.0, as {@link Double#compare} does; the
 * insertion path keeps them in the order they came, as equal positions.
 */
class EventSortTest {
    @ParameterizedTest
    @ValueSource(ints = {0, 1, 2, 5, 31, 32, 33, 100, 777, 2047, 2048, 3000, 6000})
    void sameOrderAsAStableSortOfTheDoubles(int n) {
        for (int seed = 1; seed <= 3; seed++) {
            Random r = new Random(31L * n + seed);
            double[] pos = new double[n + 9];
            int[] code = new int[n + 9];
            Integer[] order = new Integer[n];
            for (int i = 0; i < n; i++) {
                pos[7 + i] = value(r);
                code[7 + i] = EventCode.of(r.nextInt(3), r.nextInt(EventCode.MAX_PRIMITIVES));
                order[i] = 7 + i;
            }
            double[] wantPos = pos.clone();
            int[] wantCode = code.clone();
            Comparator<Integer> byPosition = n > EventSort.INSERTION ? (a, b) -> Double.compare(wantPos[a], wantPos[b])
                    : (a, b) -> wantPos[a] < wantPos[b] ? -1 : wantPos[a] > wantPos[b] ? 1 : 0;
            Arrays.sort(order, byPosition);   // stable
            EventSort sort = new EventSort();
            sort.sort(pos, code, 7, 7 + n);
            for (int i = 0; i < n; i++) {
                assertThat(Double.doubleToRawLongBits(pos[7 + i])).as("position %d", i)
                        .isEqualTo(Double.doubleToRawLongBits(wantPos[order[i]]));
                assertThat(code[7 + i]).as("code %d", i).isEqualTo(wantCode[order[i]]);
            }
            assertThat(pos[6]).as("outside the range").isZero();
            assertThat(pos[7 + n]).as("outside the range").isZero();
        }
    }

    /** A position: mostly from a few values and their neighbours a few doubles' ulps away, some zeros and huge ones. */
    private static double value(Random r) {
        return switch (r.nextInt(8)) {
            case 0 -> r.nextBoolean() ? 0.0 : -0.0;
            case 1 -> (r.nextBoolean() ? 1 : -1) * 1e39 * (1 + r.nextInt(3));
            case 2, 3 -> r.nextInt(20) * 0.1 + r.nextInt(4) * Math.ulp(1.0);
            case 4 -> (r.nextBoolean() ? 1 : -1) * 1e-46 * r.nextInt(4);
            default -> r.nextGaussian();
        };
    }
}
