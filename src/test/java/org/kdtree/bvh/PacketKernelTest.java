package org.kdtree.bvh;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.Hit;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.generate.HardMeshes;
import org.kdtree.generate.Meshes;
import org.kdtree.geom.Tolerance;
import org.kdtree.shape.TriangleMesh;

/**
 * The packet loop's kernels, the one this JVM chose ({@link PacketTraversal#KERNEL}: the Vector
 * API's on JDK 21+ with {@code jdk.incubator.vector}) and the Java 17 one, each against the
 * kernels' specification written out plainly here, ray by ray: the slabs of a box's float planes,
 * and {@link TriangleIntersector#test} over a leaf's triangles one after the other. Coherent
 * packets of a shared origin or spread origins, aimed at the scene or at a box's edges and
 * corners, with hits found earlier, any-hit rays and triangles skipped. Bit for bit.
 */
class PacketKernelTest {
    private static final double SHRINK = 1 - Tolerance.TRAVERSAL_SLACK, GROW = 1 + Tolerance.TRAVERSAL_SLACK;
    private static final int N = RayPacket.CAPACITY;
    private static final List<PacketKernel> KERNELS = List.of(PacketTraversal.KERNEL, new ScalarPacketKernel());

    private static List<TriangleMesh> meshes() {
        return List.of(Meshes.clustered(2000, 1), HardMeshes.cubeGrid(5), Meshes.planarAndDegenerate(3),
                HardMeshes.scaled(Meshes.clustered(300, 4), 1e-30), HardMeshes.scaled(HardMeshes.cubeGrid(3), 1e30));
    }

    /** A coherent packet from outside the box {@code lo..hi} towards {@code aim}, spread a little; null if it is not coherent. */
    private static RayPacket packet(Random rnd, double[] lo, double[] hi, double[] aim, boolean shared, boolean edges, PacketRays q, boolean any) {
        RayPacket p = new RayPacket();
        double[] eye = new double[3];
        for (int k = 0; k < 3; k++) eye[k] = lo[k] - (hi[k] - lo[k]) * (0.1 + rnd.nextDouble());
        int size = rnd.nextInt(4) == 0 ? 1 + rnd.nextInt(N - 1) : N;
        for (int i = 0; i < size; i++) {
            double[] o = eye.clone(), t = aim.clone();
            if (!shared) for (int k = 0; k < 3; k++) o[k] += rnd.nextDouble() * 1e-2 * (hi[k] - lo[k]);
            if (!edges) for (int k = 0; k < 3; k++) t[k] += (rnd.nextDouble() - 0.5) * 0.05 * (hi[k] - lo[k]);
            p.add(o[0], o[1], o[2], t[0] - o[0], t[1] - o[1], t[2] - o[2], rnd.nextInt(5) == 0 ? rnd.nextDouble() : 0,
                    rnd.nextInt(3) == 0 ? rnd.nextDouble() * 4 : Double.POSITIVE_INFINITY);
        }
        return q.load(p, any) ? p : null;
    }

    @Test void theNodeKernelGivesTheRaysTheSlabsSayEnter() {
        Random rnd = new Random(3);
        for (TriangleMesh mesh : meshes()) {
            Bvh bvh = new BvhBuilder().build(mesh);
            int[] nd = bvh.pairs().words;
            double[] lo = new double[3], hi = new double[3];
            for (int k = 0; k < 3; k++) { lo[k] = bvh.min(0, k); hi[k] = bvh.max(0, k); }
            PacketRays q = new PacketRays();
            for (int n = 0; n < 3000; n++) {
                int b = bvh.pairs().stride * rnd.nextInt(bvh.pairs().nodeCount()) + rnd.nextInt(2);   // child 0 or 1's first word
                double[] aim = new double[3];
                for (int k = 0, free = rnd.nextInt(4); k < 3; k++) {   // a point on an edge or corner of the box, or (n odd) anywhere
                    double min = Float.intBitsToFloat(nd[b + 4 * k]), max = Float.intBitsToFloat(nd[b + 4 * k + 2]);
                    if (!(min <= max)) { min = lo[k]; max = hi[k]; }
                    aim[k] = k == free || n % 2 == 1 ? min + rnd.nextDouble() * (max - min) : rnd.nextBoolean() ? min : max;
                }
                RayPacket p = packet(rnd, lo, hi, aim, n % 3 == 0, n % 2 == 0, q, false);
                if (p == null) continue;
                for (int i = 0; i < p.size(); i++) if (rnd.nextInt(4) == 0) q.limit[i] = rnd.nextDouble() * 3;   // a hit found earlier
                double pnx = Float.intBitsToFloat(nd[b + q.nx]), pfx = Float.intBitsToFloat(nd[b + q.fx]);
                double pny = Float.intBitsToFloat(nd[b + q.ny]), pfy = Float.intBitsToFloat(nd[b + q.fy]);
                double pnz = Float.intBitsToFloat(nd[b + q.nz]), pfz = Float.intBitsToFloat(nd[b + q.fz]);
                long want = 0;
                for (int i = 0; i < p.size(); i++) {
                    double t0 = q.start[i], t1 = q.limit[i];
                    t0 = Math.max(t0, (pnx - p.ox[i]) * p.ix[i]); t1 = Math.min(t1, (pfx - p.ox[i]) * p.ix[i]);
                    t0 = Math.max(t0, (pny - p.oy[i]) * p.iy[i]); t1 = Math.min(t1, (pfy - p.oy[i]) * p.iy[i]);
                    t0 = Math.max(t0, (pnz - p.oz[i]) * p.iz[i]); t1 = Math.min(t1, (pfz - p.oz[i]) * p.iz[i]);
                    if (t0 * SHRINK <= t1 * GROW) want |= 1L << i;
                }
                for (PacketKernel k : KERNELS) {
                    long got = 0;
                    for (int at = 0; at < N; at += k.lanes())
                        got |= (k.enter(p, q, at, pnx, pfx, pny, pfy, pnz, pfz) & (k.lanes() == 64 ? -1L : (1L << k.lanes()) - 1)) << at;
                    long inPacket = p.size() == N ? -1L : (1L << p.size()) - 1;
                    assertThat(Long.toBinaryString(got & inPacket)).as(k.getClass().getSimpleName() + ", box at " + b + ", packet " + n)
                            .isEqualTo(Long.toBinaryString(want));
                }
            }
        }
    }

    @Test void theLeafKernelGivesEachRayWhatItsTrianglesTestedOneByOneGive() {
        Random rnd = new Random(4);
        for (TriangleMesh mesh : meshes()) {
            Bvh bvh = new BvhBuilder().leafSize(1 + rnd.nextInt(16)).build(mesh);
            double[] c = bvh.leafCorners();
            double[] lo = new double[3], hi = new double[3];
            for (int k = 0; k < 3; k++) { lo[k] = bvh.min(0, k); hi[k] = bvh.max(0, k); }
            int[] leaves = java.util.stream.IntStream.range(0, bvh.nodeCount()).filter(n -> bvh.isLeaf(n) && bvh.leafSize(n) > 0).toArray();
            PacketRays q = new PacketRays();
            for (int n = 0; n < 3000; n++) {
                int leaf = leaves[rnd.nextInt(leaves.length)], from = bvh.leafStart(leaf), end = from + bvh.leafSize(leaf);
                int aimAt = 9 * (from + rnd.nextInt(end - from));
                double s = rnd.nextInt(3) / 2.0;   // a corner or an edge's middle: rays across shared edges and vertices
                double[] aim = new double[3];
                for (int k = 0; k < 3; k++) aim[k] = c[aimAt + k] * (1 - s) + c[aimAt + 3 + k] * s;
                if (!(Double.isFinite(aim[0]) && Double.isFinite(aim[1]) && Double.isFinite(aim[2]))) continue;
                boolean any = n % 3 == 0;
                RayPacket p = packet(rnd, lo, hi, aim, n % 2 == 0, n % 4 < 2, q, any);
                if (p == null) continue;
                q.frame();
                for (int i = 0; i < p.size(); i++)
                    if (!any && rnd.nextInt(3) == 0) { q.best[i] = rnd.nextDouble() * 3; q.position[i] = rnd.nextInt(bvh.primitiveCount()); }
                long skip = n % 5 == 0 ? rnd.nextLong() : 0, mask = rnd.nextInt(3) == 0 ? rnd.nextLong() : -1L;
                if (!any && n % 4 == 1) {   // ties: a hit found earlier at the very t of this leaf's hit, at a higher leaf position
                    double[][] first = state(q);
                    for (int i = 0; i < p.size(); i++)
                        if (oneByOne(p, q, c, from, end, skip, i, false, first)) { q.best[i] = first[0][i]; q.position[i] = first[1][i] + 1 + rnd.nextInt(3); }
                }
                double[][] before = {q.best.clone(), q.position.clone(), q.bu.clone(), q.bv.clone()};
                double[][] want = state(q);
                long wantHits = 0;
                for (int i = 0; i < p.size(); i++) if ((mask >>> i & 1) != 0 && oneByOne(p, q, c, from, end, skip, i, any, want)) wantHits |= 1L << i;
                for (PacketKernel k : KERNELS) {
                    restore(q, before);
                    long got = 0, group = k.lanes() == 64 ? -1L : (1L << k.lanes()) - 1;
                    for (int at = 0; at < N; at += k.lanes()) {
                        long bits = (mask >>> at) & group & (p.size() == N ? -1L : (1L << p.size()) - 1) >>> at;
                        if (bits != 0) got |= k.hit(p, q, c, from, end, skip, at, bits, any) << at;
                    }
                    String what = k.getClass().getSimpleName() + (any ? " any" : " closest") + ", leaf of " + (end - from) + ", packet " + n;
                    assertThat(Long.toBinaryString(got)).as(what).isEqualTo(Long.toBinaryString(wantHits));
                    double[][] s2 = state(q);
                    for (int a = 0; a < 4; a++)
                        for (int i = 0; i < p.size(); i++)
                            assertThat(Double.doubleToLongBits(s2[a][i])).as(what + ", ray " + i + ", field " + a).isEqualTo(Double.doubleToLongBits(want[a][i]));
                }
                restore(q, before);
            }
        }
    }

    /** The specification for ray {@code i}: each triangle tested in turn, as the single ray does; writes into {@code out}. */
    private static boolean oneByOne(RayPacket p, PacketRays q, double[] c, int from, int end, long skip, int i, boolean any, double[][] out) {
        Hit h = new Hit();
        h.primitive = (int) q.position[i];
        h.t = q.position[i] < 0 ? Double.POSITIVE_INFINITY : q.best[i];
        boolean found = false;
        for (int r = from; r < end && !(any && found); r++)
            if (r - from >= 64 || (skip >>> (r - from) & 1) == 0)
                found |= TriangleIntersector.test(c, 9 * r, r, q.okx[i], q.oky[i], q.okz[i], q.kx, q.ky, q.kz, q.sx[i], q.sy[i], q.sz[i],
                        p.tMin[i], found ? h.t : q.best[i], h);
        if (found) { out[0][i] = h.t; out[1][i] = h.primitive; out[2][i] = h.u; out[3][i] = h.v; }
        return found;
    }

    private static double[][] state(PacketRays q) {
        return new double[][] {q.best.clone(), q.position.clone(), q.bu.clone(), q.bv.clone()};
    }

    private static void restore(PacketRays q, double[][] s) {
        System.arraycopy(s[0], 0, q.best, 0, N);
        System.arraycopy(s[1], 0, q.position, 0, N);
        System.arraycopy(s[2], 0, q.bu, 0, N);
        System.arraycopy(s[3], 0, q.bv, 0, N);
    }
}
