package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The packed sort gives the very order of the doubles' stable sort ({@link EventSort}), codes
 * included: on positions closer than a float's ulp, equal ones, both zeros, flat bounds and
 * values beyond a float's range.
 */
class PackedEventSortTest {
    @ParameterizedTest
    @ValueSource(ints = {1, 2, 3, 4, 5})
    void sameOrderAsTheSortOfTheDoubles(int seed) {
        Random r = new Random(seed);
        int k = 3, n = 3000 + r.nextInt(3000);
        double[] bounds = new double[2 * k * (n + 7)];
        int[] refs = new int[n + 7];
        for (int j = 0; j < n; j++) refs[7 + j] = 2 * j + r.nextInt(2);
        for (int j = 0; j < n; j++) for (int a = 0; a < k; a++) {
            double lo = value(r), hi = r.nextInt(5) == 0 ? lo : Math.max(lo, value(r));
            if (lo == hi && r.nextBoolean()) hi = Math.nextUp(lo);
            bounds[2 * k * (7 + j) + a] = lo;
            bounds[2 * k * (7 + j) + k + a] = hi;
        }
        for (int axis = 0; axis < k; axis++) {
            int events = 0;
            for (int j = 0; j < n; j++) events += bounds[2 * k * (7 + j) + axis] == bounds[2 * k * (7 + j) + k + axis] ? 1 : 2;
            double[] wantPos = new double[events + 5], gotPos = new double[events + 5];
            int[] wantCode = new int[events + 5], gotCode = new int[events + 5];
            int m = 5;
            for (int j = 0; j < n; j++) m = EventRoot.addEvents(bounds, k, 7 + j, refs[7 + j], axis, wantPos, wantCode, m);
            EventSort.sort(wantPos, wantCode, 5, m, new double[events], new int[events]);
            PackedEventSort.write(bounds, k, refs, 7, n, axis, gotPos, gotCode, 5, new long[events], new long[events], new double[events],
                    new int[PackedEventSort.countLength()]);
            for (int i = 5; i < m; i++) {
                assertThat(Double.doubleToRawLongBits(gotPos[i])).as("position %d", i).isEqualTo(Double.doubleToRawLongBits(wantPos[i]));
                assertThat(gotCode[i]).as("code %d", i).isEqualTo(wantCode[i]);
            }
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
