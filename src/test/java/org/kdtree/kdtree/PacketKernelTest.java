package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.Hit;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.accel.Vectorization;

/**
 * The packet loop's kernels ({@link PacketKernel}) against the single-ray rules, lane by lane and
 * bit for bit: the node kernel against {@link MeshTraversal}'s decision at a split plane, the leaf
 * kernels against {@link TriangleIntersector#test} run over the leaf's triangles for each lane
 * alone. Held to them: the scalar kernel everywhere, and the kernel this JVM's packet loops call
 * (the Vector API one on JDK 21 or newer with {@code jdk.incubator.vector}, as CI's second run
 * has it), so a kernel broken on purpose fails on the JDK that runs it. Random lanes, and the hard
 * ones: axis-parallel rays (an inverse direction of +-infinity, a tSplit of NaN for an origin on the
 * plane), origins on the split plane, ties of tSplit with either end of the interval, lanes whose
 * shear axes differ within a group, rays through shared edges and vertices, duplicate triangles
 * (the lower index wins a tie) and hits exactly at the interval's ends.
 */
class PacketKernelTest {
    private static final int N = PacketLanes.N;
    private static final double SLACK = Traverser.SLACK;

    /** The kernels held to the rules: the scalar one, and the one this JVM's packet loops call if it is another. */
    private static List<PacketKernel> kernels() {
        List<PacketKernel> k = new ArrayList<>(List.of(new ScalarPacketKernel()));
        if (PacketTraversal.vectorKernels()) k.add(PacketTraversal.KERNEL);
        return k;
    }

    @Test void theJvmSaysWhichKernelsThePacketLoopCalls() {
        boolean vectorJdk = Runtime.version().feature() >= Vectorization.JDK
                && ModuleLayer.boot().findModule(Vectorization.MODULE).isPresent() && !"false".equals(System.getProperty("kdtree.vector"));
        assertThat(PacketTraversal.vectorKernels()).as("vector kernels on a JDK with the Vector API").isEqualTo(vectorJdk);
        assertThat(PacketTraversal.KERNEL.getClass().getSimpleName()).isEqualTo(vectorJdk ? "VectorPacketKernel" : "ScalarPacketKernel");
    }

    // ---- the node kernel

    @Test void theNodeKernelSendsEachLaneWhereItsRayGoesAlone() {
        long[] seen = new long[4];                  // lanes that went near only, far only, both ways, both in the plane
        for (long seed = 0; seed < 3000; seed++) {
            SplittableRandom rnd = new SplittableRandom(seed);
            int axis = rnd.nextInt(3);
            double plane = rnd.nextInt(4) == 0 ? 0.5 : rnd.nextDouble(-2, 2);
            long active = activeLanes(rnd);
            PacketLanes want = nodeLanes(seed, axis, plane);
            double[] wantMin = new double[2 * N], wantMax = new double[2 * N];
            long[] ways = reference(want, active, axis, plane, wantMin, wantMax, N);
            seen[0] += Long.bitCount(ways[0] & ~ways[1]);
            seen[1] += Long.bitCount(ways[1] & ~ways[0]);
            seen[2] += Long.bitCount(ways[0] & ways[1]);
            for (long m = ways[0] & ways[1]; m != 0; m &= m - 1) if (wantMin[N + Long.numberOfTrailingZeros(m)] == want.curMin[Long.numberOfTrailingZeros(m)]) seen[3]++;
            for (PacketKernel k : kernels()) {
                PacketLanes got = nodeLanes(seed, axis, plane);
                double[] farMin = new double[2 * N], farMax = new double[2 * N];
                k.node(got, active, axis, plane, farMin, farMax, N);
                String what = k.getClass().getSimpleName() + " seed " + seed;
                assertThat(got.toNear).as(what + " near lanes").isEqualTo(ways[0]);
                assertThat(got.toFar).as(what + " far lanes").isEqualTo(ways[1]);
                for (int i = 0; i < N; i++) {
                    String lane = what + " lane " + i;
                    if ((ways[1] >>> i & 1) != 0) {
                        assertThat(bits(farMin[N + i])).as(lane + " far start").isEqualTo(bits(wantMin[N + i]));
                        assertThat(bits(farMax[N + i])).as(lane + " far end").isEqualTo(bits(wantMax[N + i]));
                    }
                    assertThat(bits(got.curMin[i])).as(lane + " curMin").isEqualTo(bits(want.curMin[i]));
                    assertThat(bits(got.curMax[i])).as(lane + " curMax").isEqualTo(bits(want.curMax[i]));
                    assertThat(bits(got.lo[i])).as(lane + " lo").isEqualTo(bits(want.lo[i]));
                    assertThat(bits(got.hi[i])).as(lane + " hi").isEqualTo(bits(want.hi[i]));
                }
            }
        }
        assertThat(java.util.Arrays.stream(seen).min().getAsLong()).as("fewest lanes of near only, far only, both ways, in the plane").isGreaterThan(1000);
    }

    @Test void aSavedChildIsTakenUpByTheLanesThatStartNoFartherThanTheirHit() {
        long taken = 0;
        for (long seed = 0; seed < 3000; seed++) {
            SplittableRandom rnd = new SplittableRandom(seed);
            long saved = activeLanes(rnd);
            double[] farMin = new double[2 * N], farMax = new double[2 * N];
            for (int i = 0; i < N; i++) {
                farMin[N + i] = rnd.nextDouble(-1, 3);
                farMax[N + i] = farMin[N + i] + rnd.nextDouble() * 2;
            }
            PacketLanes want = resumeLanes(seed, farMin);
            long wantTaken = 0;
            for (int i = 0; i < N; i++) {                // MeshTraversal's pop, lane by lane
                double start = farMin[N + i], best = want.bestT[i];
                if ((saved >>> i & 1) == 0 || !(start <= best + Math.abs(best) * SLACK)) continue;
                wantTaken |= 1L << i;
                want.curMin[i] = start;
                want.curMax[i] = farMax[N + i];
                want.lo[i] = start - Math.abs(start) * SLACK;
                want.hi[i] = farMax[N + i] + Math.abs(farMax[N + i]) * SLACK;
            }
            taken += Long.bitCount(wantTaken);
            for (PacketKernel k : kernels()) {
                PacketLanes got = resumeLanes(seed, farMin);
                String what = k.getClass().getSimpleName() + " seed " + seed;
                assertThat(k.resume(got, saved, farMin, farMax, N)).as(what + " lanes taken").isEqualTo(wantTaken);
                for (int i = 0; i < N; i++) {
                    String lane = what + " lane " + i;
                    assertThat(bits(got.curMin[i])).as(lane + " curMin").isEqualTo(bits(want.curMin[i]));
                    assertThat(bits(got.curMax[i])).as(lane + " curMax").isEqualTo(bits(want.curMax[i]));
                    assertThat(bits(got.lo[i])).as(lane + " lo").isEqualTo(bits(want.lo[i]));
                    assertThat(bits(got.hi[i])).as(lane + " hi").isEqualTo(bits(want.hi[i]));
                }
            }
        }
        assertThat(taken).as("lanes that took a child up").isGreaterThan(20_000);
    }

    /**
     * Lanes with a closest hit so far that is none, random, at the saved child's start, just beyond
     * the slack from it, or (a tie) exactly the slack from it: then the start is moved there.
     */
    private static PacketLanes resumeLanes(long seed, double[] farMin) {
        SplittableRandom rnd = new SplittableRandom(seed * 17 + 3);
        PacketLanes l = new PacketLanes();
        for (int i = 0; i < N; i++) {
            double start = farMin[N + i];
            l.curMin[i] = l.lo[i] = -5;
            l.curMax[i] = l.hi[i] = -4;
            l.bestT[i] = switch (rnd.nextInt(6)) {
                case 0 -> Double.POSITIVE_INFINITY;
                case 1 -> start;                                          // a hit right at the child's start: taken up
                case 2 -> Math.nextDown(start - Math.abs(start) * SLACK); // just beyond the slack: not
                case 3 -> {                                               // the start exactly at the hit plus the slack: taken up
                    double best = rnd.nextDouble(-1, 4);
                    farMin[N + i] = best + Math.abs(best) * SLACK;
                    yield best;
                }
                default -> rnd.nextDouble(-1, 4);
            };
        }
        return l;
    }

    /** MeshTraversal's decision at an interior node, lane by lane: {@return the near and the far lanes} */
    private static long[] reference(PacketLanes l, long active, int axis, double plane, double[] farMin, double[] farMax, int at) {
        long near = 0, far = 0;
        for (int i = 0; i < N; i++) {
            if ((active >>> i & 1) == 0) continue;
            double tSplit = (plane - l.origin[axis][i]) * l.inverse[axis][i];
            if (tSplit > l.hi[i]) {
                near |= 1L << i;
            } else if (tSplit < l.lo[i]) {
                far |= 1L << i;
                farMin[at + i] = l.curMin[i];
                farMax[at + i] = l.curMax[i];
            } else {
                near |= 1L << i;
                far |= 1L << i;
                farMax[at + i] = l.curMax[i];
                if (tSplit != tSplit) {          // the ray lies in the split plane
                    farMin[at + i] = l.curMin[i];
                } else {
                    farMin[at + i] = tSplit;
                    l.curMax[i] = tSplit;
                    l.hi[i] = tSplit + Math.abs(tSplit) * SLACK;
                }
            }
        }
        return new long[] {near, far};
    }

    /** Lanes made from {@code seed}: random rays, a quarter axis-parallel, some from the plane, intervals with ties at tSplit. */
    private static PacketLanes nodeLanes(long seed, int axis, double plane) {
        SplittableRandom rnd = new SplittableRandom(seed * 31 + 7);
        RayPacket p = new RayPacket();
        for (int i = 0; i < N; i++) {
            double[] o = {rnd.nextDouble(-2, 2), rnd.nextDouble(-2, 2), rnd.nextDouble(-2, 2)};
            double[] d = {rnd.nextDouble(-1, 1), rnd.nextDouble(-1, 1), rnd.nextDouble(-1, 1)};
            switch (rnd.nextInt(6)) {
                case 0 -> d[axis] = rnd.nextBoolean() ? 0.0 : -0.0;                  // parallel to the plane: tSplit +-infinity
                case 1 -> { o[axis] = plane; d[axis] = rnd.nextBoolean() ? 0.0 : -0.0; }   // in the plane: tSplit NaN
                case 2 -> o[axis] = plane;                                           // from the plane: tSplit 0 (or -0)
                default -> { }
            }
            p.add(o[0], o[1], o[2], d[0], d[1], d[2], 0, Double.POSITIVE_INFINITY);
        }
        PacketLanes l = new PacketLanes();
        l.clearAxes();
        for (int i = 0; i < N; i++) {
            l.load(p, i);
            double tSplit = (plane - l.origin[axis][i]) * l.inverse[axis][i];
            double a = rnd.nextDouble(-1, 3), b = a + rnd.nextDouble() * 3;
            l.curMin[i] = a;
            l.curMax[i] = b;
            l.lo[i] = a - Math.abs(a) * SLACK;
            l.hi[i] = b + Math.abs(b) * SLACK;
            if (tSplit - tSplit == 0) {
                switch (rnd.nextInt(5)) {
                    case 0 -> l.hi[i] = tSplit;                                      // a tie at the interval's end
                    case 1 -> l.lo[i] = tSplit;                                      // a tie at its start
                    case 2 -> { l.lo[i] = tSplit; l.hi[i] = tSplit; }                // an interval of one t
                    default -> { }
                }
            }
        }
        return l;
    }

    // ---- the leaf kernels

    @Test void theLeafKernelsFindEachLanesHitAsTheSingleRayTestDoes() {
        double[] c = triangles();
        int triangles = c.length / 9;
        long hits = 0, ties = 0;
        for (long seed = 0; seed < 1500; seed++) {
            SplittableRandom rnd = new SplittableRandom(seed);
            int[] refs = leaf(rnd, triangles);
            int start = rnd.nextInt(3), end = start + rnd.nextInt(refs.length - start + 1);
            long active = activeLanes(rnd);
            for (boolean any : new boolean[] {false, true}) {
                PacketLanes want = leafLanes(seed, c);
                double[] before = want.bestPrim.clone();
                long wantHit = reference(want, active, refs, start, end, c, any);
                hits += Long.bitCount(wantHit);
                for (int i = 0; i < N; i++) if (before[i] == triangles - 3 && want.bestPrim[i] == 3) ties++;
                for (PacketKernel k : kernels()) {
                    PacketLanes got = leafLanes(seed, c);
                    String what = k.getClass().getSimpleName() + (any ? " any" : " closest") + " seed " + seed;
                    if (any) assertThat(k.any(got, active, refs, start, end, c)).as(what + " lanes that hit").isEqualTo(wantHit);
                    else k.closest(got, active, refs, start, end, c);
                    for (int i = 0; i < N; i++) {
                        String lane = what + " lane " + i;
                        if (!any || (wantHit >>> i & 1) == 0)
                            assertThat(got.bestPrim[i]).as(lane + " primitive").isEqualTo(want.bestPrim[i]);
                        if (any) continue;                   // which hit an any-hit lane keeps is unspecified
                        assertThat(bits(got.bestT[i])).as(lane + " t").isEqualTo(bits(want.bestT[i]));
                        assertThat(bits(got.bestU[i])).as(lane + " u").isEqualTo(bits(want.bestU[i]));
                        assertThat(bits(got.bestV[i])).as(lane + " v").isEqualTo(bits(want.bestV[i]));
                    }
                }
            }
        }
        assertThat(hits).as("lanes that hit").isGreaterThan(5_000);
        assertThat(ties).as("ties won by the lower index").isGreaterThan(0);
    }

    /** Each active lane alone: {@link TriangleIntersector#test} over the leaf's triangles in order. {@return the lanes that hit} */
    private static long reference(PacketLanes l, long active, int[] refs, int start, int end, double[] c, boolean any) {
        long hit = 0;
        Hit h = new Hit();
        for (int i = 0; i < N; i++) {
            if ((active >>> i & 1) == 0) continue;
            h.primitive = (int) l.bestPrim[i];
            h.t = l.bestT[i];
            h.u = l.bestU[i];
            h.v = l.bestV[i];
            for (int r = start; r < end; r++) {
                if (!TriangleIntersector.test(c, 9 * refs[r], refs[r], l.okx[i], l.oky[i], l.okz[i], l.kx[i], l.ky[i], l.kz[i],
                        l.sx[i], l.sy[i], l.sz[i], l.tMin[i], l.tMax[i], h)) continue;
                hit |= 1L << i;
                if (any) break;
            }
            l.bestPrim[i] = h.primitive;
            l.bestT[i] = h.t;
            l.bestU[i] = h.u;
            l.bestV[i] = h.v;
        }
        return hit;
    }

    /**
     * The triangles: a unit grid of quads in the z = 1 plane, two triangles each (shared edges and
     * vertices), the same grid tilted and in the x = 1 plane (so that rays meet them with other
     * dominant axes), a duplicate of triangle 3 at index 4 * 4 * 2 * 3 (the lower index wins the
     * tie), a triangle seen edge-on from the axes' rays and a zero-area one.
     */
    private static double[] triangles() {
        List<double[]> t = new ArrayList<>();
        for (int grid = 0; grid < 3; grid++)
            for (int i = 0; i < 4; i++)
                for (int j = 0; j < 4; j++) {
                    double[][] q = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
                    for (int[] tri : new int[][] {{0, 1, 2}, {0, 2, 3}}) {
                        double[] corners = new double[9];
                        for (int k = 0; k < 3; k++) {
                            double a = q[tri[k]][0], b = q[tri[k]][1];
                            double[] v = grid == 0 ? new double[] {a, b, 1} : grid == 1 ? new double[] {a, b, 1 + 0.25 * a + 0.125 * b} : new double[] {1, a, b};
                            System.arraycopy(v, 0, corners, 3 * k, 3);
                        }
                        t.add(corners);
                    }
                }
        t.add(t.get(3).clone());
        t.add(new double[] {0, 0, 2, 4, 0, 2, 4, 4, 2.0000001});
        t.add(new double[] {0, 0, 3, 1, 1, 3, 2, 2, 3});
        double[] c = new double[9 * t.size()];
        for (int i = 0; i < t.size(); i++) System.arraycopy(t.get(i), 0, c, 9 * i, 9);
        return c;
    }

    /** A leaf's references: a random selection in random order, the duplicate pair (higher index first) in it. */
    private static int[] leaf(SplittableRandom rnd, int triangles) {
        int n = 2 + rnd.nextInt(12);
        int[] refs = new int[n + 2];
        for (int i = 0; i < n; i++) refs[i] = rnd.nextInt(triangles);
        refs[n] = triangles - 3;
        refs[n + 1] = 3;
        for (int i = refs.length - 1; i > 0; i--) {
            int j = rnd.nextInt(i + 1), s = refs[i];
            refs[i] = refs[j];
            refs[j] = s;
        }
        return refs;
    }

    /**
     * Lanes made from {@code seed}: rays at shared vertices and edge midpoints of the grids or at
     * random points, from random origins (so that lanes of one group shear on different axes), or
     * along an axis; intervals ending or starting exactly at a hit; some lanes with a hit before.
     */
    private static PacketLanes leafLanes(long seed, double[] c) {
        SplittableRandom rnd = new SplittableRandom(seed * 131 + 5);
        RayPacket p = new RayPacket();
        for (int i = 0; i < N; i++) {
            double[] o = {rnd.nextDouble(-3, 7), rnd.nextDouble(-3, 7), rnd.nextDouble(-3, 7)};
            double[] to;
            switch (rnd.nextInt(4)) {
                case 0 -> to = new double[] {rnd.nextInt(9) * 0.5, rnd.nextInt(9) * 0.5, 1};            // vertices and edge midpoints, z = 1
                case 1 -> to = new double[] {1, rnd.nextInt(9) * 0.5, rnd.nextInt(9) * 0.5};            // the same in x = 1
                case 2 -> { to = new double[] {rnd.nextInt(5), rnd.nextInt(5), 1}; o = new double[] {to[0], to[1], rnd.nextBoolean() ? 5 : -3}; }
                default -> to = new double[] {rnd.nextDouble(0, 4), rnd.nextDouble(0, 4), rnd.nextDouble(0, 4)};
            }
            double tMin = 0, tMax = Double.POSITIVE_INFINITY;
            p.add(o[0], o[1], o[2], to[0] - o[0], to[1] - o[1], to[2] - o[2], tMin, tMax);
        }
        PacketLanes l = new PacketLanes();
        l.clearAxes();
        Hit h = new Hit();
        for (int i = 0; i < N; i++) {
            l.load(p, i);
            h.reset();
            for (int t = 0; t < c.length / 9; t++)
                TriangleIntersector.test(c, 9 * t, t, l.okx[i], l.oky[i], l.okz[i], l.kx[i], l.ky[i], l.kz[i], l.sx[i], l.sy[i], l.sz[i], 0,
                        Double.POSITIVE_INFINITY, h);
            if (!h.found()) continue;
            switch (rnd.nextInt(5)) {
                case 0 -> l.tMax[i] = h.t;                                         // a hit at the interval's end
                case 1 -> l.tMin[i] = h.t;                                         // at its start
                case 2 -> { l.bestPrim[i] = c.length / 9 - 3; l.bestT[i] = h.t; } // an earlier hit as close, by a higher index
                case 3 -> { l.bestPrim[i] = h.primitive; l.bestT[i] = h.t; l.bestU[i] = h.u; l.bestV[i] = h.v; }
                default -> { }
            }
        }
        return l;
    }

    /** All lanes, none, one, or a random set. */
    private static long activeLanes(SplittableRandom rnd) {
        return switch (rnd.nextInt(6)) {
            case 0 -> -1L;
            case 1 -> 0;
            case 2 -> 1L << rnd.nextInt(N);
            default -> rnd.nextLong();
        };
    }

    private static long bits(double x) {
        return Double.doubleToLongBits(x);
    }
}
