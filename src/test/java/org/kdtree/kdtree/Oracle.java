package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.BruteForce;
import org.kdtree.accel.Hit;
import org.kdtree.accel.Intersector;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.TraversalStats;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.geom.Ray;
import org.kdtree.geom.Tolerance;
import org.kdtree.shape.Primitives;
import org.kdtree.spec.BuilderSpec;
import org.kdtree.spec.Builders;

/**
 * The test oracle: a kd-tree's or a BVH's query must agree with brute force over all primitives. Same hit or
 * miss; the same closest t within {@link #TOLERANCE} (relative 1e-9); the same primitive, or
 * another that the ray meets equally close.
 */
final class Oracle {
    static final Tolerance TOLERANCE = new Tolerance(1e-9, 1e-300);

    final Intersector prims;
    final BruteForce brute;
    /** The kd-tree's traverser (null for a BVH), for the queries only a kd-tree answers. */
    final Traverser traverser;
    final RayQuery fast, listened;
    final String name;
    private final Hit expected = new Hit(), actual = new Hit(), probe = new Hit();
    final TraversalStats stats = new TraversalStats();

    Oracle(Primitives scene, Intersector prims, String builder) {
        this(prims, builder.equals(BvhBuilder.NAME) ? new BvhBuilder().build(scene)
                : (AccelerationStructure) Builders.create(builder).build(scene), builder);
    }

    Oracle(Intersector prims, AccelerationStructure structure, String name) {
        this.prims = prims;
        this.brute = new BruteForce(prims);
        this.traverser = structure instanceof KdTree kd ? new Traverser(kd) : null;
        this.fast = structure.query();
        this.listened = structure.query(stats);
        this.name = name;
    }

    /**
     * One oracle per registered builder, one for the BVH (traced 4 wide), and one for the BVH
     * traced on its compact binary layout (width 2: one cache line per node).
     */
    static List<Oracle> allBuilders(Primitives scene, Intersector prims) {
        List<Oracle> all = new java.util.ArrayList<>(BuilderSpec.names().stream().map(b -> new Oracle(scene, prims, b)).toList());
        all.add(new Oracle(prims, new BvhBuilder().width(2).build(scene), BvhBuilder.NAME + "-width2"));
        return List.copyOf(all);
    }

    /** {@link #allBuilders}, and one per builder and the BVH for its structure saved to a tree file and loaded again: the hard cases' oracles. */
    static List<Oracle> allBuildersAndSavedTrees(Primitives scene, Intersector prims) {
        List<Oracle> all = new java.util.ArrayList<>(allBuilders(scene, prims));
        for (String b : BuilderSpec.names()) all.add(new Oracle(prims, savedAndLoaded(BuilderSpec.of(b), scene), b + " saved and loaded"));
        return List.copyOf(all);
    }

    /** {@code spec}'s structure over {@code scene}, written to a tree file's bytes and read back (issue 43: the hard cases through a load). */
    static AccelerationStructure savedAndLoaded(BuilderSpec spec, Primitives scene) {
        try {
            java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
            org.kdtree.treefile.TreeFile.write(out, spec.build(scene, null), spec, scene);
            return org.kdtree.treefile.TreeFile.read(new java.io.ByteArrayInputStream(out.toByteArray()), spec.builder(), scene).structure();
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** Checks closest hit (fast and generic paths), any hit and all hits; returns whether it hit. */
    boolean check(Ray ray, double tMin, double tMax) {
        boolean want = brute.closestHit(ray, tMin, tMax, expected);
        boolean got = fast.closestHit(ray, tMin, tMax, actual);
        compare(ray, want, got, "closestHit", tMin, tMax);
        boolean gotGeneric = listened.closestHit(ray, tMin, tMax, actual);
        compare(ray, want, gotGeneric, "closestHit(listener)", tMin, tMax);
        assertThat(fast.anyHit(ray, tMin, tMax)).as(context(ray, "anyHit", tMin, tMax)).isEqualTo(want);
        assertThat(listened.anyHit(ray, tMin, tMax)).as(context(ray, "anyHit(listener)", tMin, tMax))
                .isEqualTo(want);
        return want;
    }

    boolean check(Ray ray) {
        return check(ray, 0, Double.POSITIVE_INFINITY);
    }

    /** The closest hit of the tree (fast path), after checking it. */
    Hit closest(Ray ray) {
        check(ray);
        fast.closestHit(ray, 0, Double.POSITIVE_INFINITY, actual);
        return actual;
    }

    private void compare(Ray ray, boolean want, boolean got, String query, double tMin, double tMax) {
        String ctx = context(ray, query, tMin, tMax);
        assertThat(got).as(ctx + " found (brute force: " + expected + ", tree: " + actual + ")").isEqualTo(want);
        if (!want) return;
        assertThat(TOLERANCE.equal(actual.t, expected.t)).as(ctx + " t: tree " + actual + " vs brute " + expected)
                .isTrue();
        if (actual.primitive != expected.primitive) {
            probe.reset();
            boolean hits = prims.intersect(actual.primitive, ray, tMin, tMax, probe);
            assertThat(hits && TOLERANCE.equal(probe.t, expected.t))
                    .as(ctx + " tree's primitive is not equally close: tree " + actual + " vs brute " + expected).isTrue();
        }
    }

    private String context(Ray ray, String query, double tMin, double tMax) {
        return name + " " + query + " " + ray + " [" + tMin + ", " + tMax + "]";
    }
}
