package org.kdtree.collide;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import java.util.List;
import org.kdtree.shape.Primitives;
import org.kdtree.spec.Builders;

/**
 * The test oracle: the tree queries must agree with brute force over all primitives. Both run the
 * same exact primitive test on the same numbers, so they must agree exactly: the same set of
 * overlapping primitives, the same first contact t to the last bit, the same primitive (ties go
 * to the smallest index in both).
 */
final class CollideOracle {
    final String name;
    final OverlapQuery overlap;
    final SweepQuery sweep;
    final BruteForceCollisions brute;
    private final int[] want, got;
    private final Contact expected = new Contact(), actual = new Contact();

    CollideOracle(Primitives scene, Collider prims, String builder) {
        this.name = builder;
        var tree = Builders.create(builder).build(scene);
        overlap = new OverlapQuery(tree, prims);
        sweep = new SweepQuery(tree, prims);
        brute = new BruteForceCollisions(prims);
        want = new int[prims.size()];
        got = new int[prims.size()];
    }

    /** One oracle per registered builder. */
    static List<CollideOracle> allBuilders(Primitives scene, Collider prims) {
        return Builders.names().stream().map(b -> new CollideOracle(scene, prims, b)).toList();
    }

    /** Checks the overlap query; returns the sorted overlapping primitives. */
    int[] checkOverlap(double[] centre, double r) {
        int n = brute.overlapping(centre, r, want);
        int m = overlap.overlapping(centre, r, got);
        int[] w = Arrays.copyOf(want, n), g = Arrays.copyOf(got, m);
        Arrays.sort(g);
        assertThat(g).as(name + " overlapping(" + Arrays.toString(centre) + ", r=" + r + ")").isEqualTo(w);
        assertThat(overlap.lastTests()).isLessThanOrEqualTo(want.length);
        return w;
    }

    /** Checks the swept query; returns brute force's contact (a copy of its primitive and t in a new Contact). */
    Contact checkSweep(double[] s, double[] d, double r) {
        boolean w = brute.firstContact(s, d, r, expected);
        boolean g = sweep.firstContact(s, d, r, actual);
        String ctx = name + " firstContact(" + Arrays.toString(s) + " + t " + Arrays.toString(d) + ", r=" + r + ")";
        assertThat(g).as(ctx + " found; brute " + expected + ", tree " + actual).isEqualTo(w);
        assertThat(actual.primitive).as(ctx + " primitive").isEqualTo(expected.primitive);
        assertThat(actual.t).as(ctx + " t").isEqualTo(expected.t);
        assertThat(actual.point).as(ctx + " point").isEqualTo(expected.point);
        assertThat(actual.normal).as(ctx + " normal").isEqualTo(expected.normal);
        return expected;
    }
}
