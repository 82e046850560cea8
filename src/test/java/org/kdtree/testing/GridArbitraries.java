package org.kdtree.testing;

import java.util.List;
import net.jqwik.api.Arbitraries;
import net.jqwik.api.Arbitrary;
import net.jqwik.api.Combinators;

/**
 * Random 3-D geometry on a coarse grid (multiples of 1/4 in [0, 4]), so that coincident planes,
 * shared vertices, planar and degenerate triangles, and queries through vertices or in split
 * planes come up often: the property tests of the ray traversal and of the collision queries.
 */
public final class GridArbitraries {
    private GridArbitraries() {
    }

    /** {@return a grid coordinate, a multiple of 1/4 in [0, 4]} */
    public static Arbitrary<Double> coord() {
        return Arbitraries.integers().between(0, 16).map(i -> i / 4.0);
    }

    /** {@return a grid point {x, y, z}} */
    public static Arbitrary<double[]> point() {
        return Combinators.combine(coord(), coord(), coord()).as((x, y, z) -> new double[] {x, y, z});
    }

    /** {@return 1 to 40 triangles of grid points, each as nine coordinates} */
    public static Arbitrary<List<double[]>> triangles() {
        return point().list().ofSize(3).list().ofMinSize(1).ofMaxSize(40)
                .map(ts -> ts.stream().map(t -> new double[] {t.get(0)[0], t.get(0)[1], t.get(0)[2], t.get(1)[0],
                        t.get(1)[1], t.get(1)[2], t.get(2)[0], t.get(2)[1], t.get(2)[2]}).toList());
    }
}
