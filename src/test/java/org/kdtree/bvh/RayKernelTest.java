package org.kdtree.bvh;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.Hit;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.accel.Vectorization;
import org.kdtree.generate.HardMeshes;
import org.kdtree.generate.Meshes;
import org.kdtree.geom.Tolerance;
import org.kdtree.shape.TriangleMesh;

/**
 * The single-ray loop's kernels, the one this JVM chose ({@link WideTraversal#KERNEL}: the Vector
 * API's on JDK 21+ with {@code jdk.incubator.vector}, as CI's second run has it) and the Java 17
 * one, each against the kernels' specification written out plainly here: per child the slabs of
 * its float box, per leaf {@link TriangleIntersector#test} one triangle after the other. Nodes of
 * real hierarchies at every width, rays at random, from far away, nearly parallel to an axis
 * (inverse directions near 1e300), through box faces, edges and shared vertices; planes at
 * infinity (unused slots). Bit for bit: the entry distances and hits as doubles.
 */
class RayKernelTest {
    private static final double SHRINK = 1 - Tolerance.TRAVERSAL_SLACK, GROW = 1 + Tolerance.TRAVERSAL_SLACK;
    private static final List<RayKernel> KERNELS = List.of(WideTraversal.KERNEL, new ScalarRayKernel());

    @Test void theJvmsKernelIsTheOneItsPathSays() {
        assertThat(WideTraversal.KERNEL.getClass().getSimpleName())
                .isEqualTo(Vectorization.enabled() ? "VectorRayKernel" : "ScalarRayKernel");
    }

    private static List<TriangleMesh> meshes() {
        return List.of(Meshes.clustered(2000, 1), Meshes.surface(1500, 2), HardMeshes.cubeGrid(5), Meshes.planarAndDegenerate(3),
                HardMeshes.scaled(HardMeshes.cubeGrid(3), 1e30), HardMeshes.scaled(Meshes.clustered(300, 4), 1e-30));
    }

    /** A ray of the kind {@code n} picks: origin (3), direction (3), inverse direction (3). */
    private static double[] ray(Random rnd, int n, double[] lo, double[] hi, double[] lattice) {
        double[] r = new double[9];
        for (int k = 0; k < 3; k++) {
            double ext = hi[k] - lo[k];
            r[k] = switch (n % 5) {
                case 0 -> lo[k] + rnd.nextDouble() * ext;                        // inside
                case 1 -> lo[k] + (rnd.nextDouble() - 0.5) * ext * 1e6;         // far away
                case 2 -> rnd.nextBoolean() ? lo[k] : hi[k];                     // on the box's faces and edges
                case 3 -> lattice[rnd.nextInt(lattice.length) / 3 * 3 + k];      // on a vertex
                default -> lo[k] + Math.floor(rnd.nextDouble() * 4) * ext / 4;  // on a lattice
            };
            r[3 + k] = rnd.nextGaussian();
        }
        if (n % 3 == 0) r[3 + rnd.nextInt(3)] = (rnd.nextBoolean() ? 1 : -1) * 1e-300 * (1 + rnd.nextDouble());   // nearly axis-parallel
        if (n % 5 == 1) for (int k = 0; k < 3; k++) r[3 + k] = lo[k] + rnd.nextDouble() * (hi[k] - lo[k]) - r[k];  // aimed at the scene
        for (int k = 0; k < 3; k++) r[6 + k] = 1 / r[3 + k];
        return r;
    }

    @Test void theNodeKernelEntersTheChildrenTheSlabsSayFromTheirEntryDistance() {
        Random rnd = new Random(5);
        for (int width = 2; width <= 8; width++) {
            for (TriangleMesh mesh : meshes()) {
                Bvh bvh = new BvhBuilder().width(width).build(mesh);
                WideNodes w = new WideNodes(bvh, width);   // every width, whichever the JVM's path traces
                double[] vertices = mesh.vertices();
                double[] lo = new double[3], hi = new double[3];
                for (int k = 0; k < 3; k++) { lo[k] = bvh.min(0, k); hi[k] = bvh.max(0, k); }
                double[] t = new double[width + RayKernel.SPARE], want = new double[width];
                int[] entries = new int[width];
                for (int n = 0; n < 3000; n++) {
                    double[] r = ray(rnd, n, lo, hi, vertices);
                    int node = rnd.nextInt(w.nodeCount()), base = w.stride * node;
                    if (n % 2 == 1) {   // aimed at an edge or a corner of one of the node's child boxes: t0 and t1 within rounding
                        int slot = rnd.nextInt(width);
                        for (int a = 0, free = rnd.nextInt(4); a < 3; a++) {
                            float min = Float.intBitsToFloat(w.words[base + 2 * width * a + slot]);
                            float max = Float.intBitsToFloat(w.words[base + 2 * width * a + width + slot]);
                            if (!(min <= max)) break;
                            double at = a == free ? min + rnd.nextDouble() * (max - min) : rnd.nextBoolean() ? min : max;
                            r[3 + a] = at - r[a];
                            r[6 + a] = 1 / r[3 + a];
                        }
                        if (!(Double.isFinite(r[6]) && Double.isFinite(r[7]) && Double.isFinite(r[8]))) continue;
                    }
                    int nx = r[6] < 0 ? width : 0, ny = (r[7] < 0 ? width : 0) + 2 * width, nz = (r[8] < 0 ? width : 0) + 4 * width;
                    double start = n % 4 == 0 ? rnd.nextDouble() : 0, limit = n % 7 == 0 ? rnd.nextDouble() * 10 : Double.POSITIVE_INFINITY;
                    int bits = slabs(w, base, r, start, limit, want);
                    for (RayKernel kernel : KERNELS) {
                        int got = kernel.enter(w.words, base, width, nx, width - nx, ny, 5 * width - ny, nz, 9 * width - nz, r[0], r[1], r[2], r[6], r[7], r[8], start, limit, entries, t);
                        String what = kernel.getClass().getSimpleName() + ", width " + width + ", node " + node + ", ray " + java.util.Arrays.toString(r);
                        assertThat(got).as(what).isEqualTo(Integer.bitCount(bits));
                        for (int i = 0, m = 0; i < width; i++) {   // the slots entered, in slot order
                            if ((bits >> i & 1) == 0) continue;
                            int ref = base + w.refs + i;
                            assertThat(entries[m]).as(what + ", slot " + i).isEqualTo(w.words[ref + width] > 0 ? -1 - ref : w.words[ref]);
                            assertThat(Double.doubleToLongBits(t[m++])).as(what + ", slot " + i).isEqualTo(Double.doubleToLongBits(want[i]));
                        }
                    }
                }
            }
        }
    }

    /** The specification: per child slot, its box's slabs in double from the float planes, the interval clipped to [start, limit], slack. */
    private static int slabs(WideNodes w, int base, double[] r, double start, double limit, double[] t) {
        int bits = 0;
        for (int i = 0; i < w.width; i++) {
            double t0 = start, t1 = limit;
            for (int a = 0; a < 3; a++) {
                double min = Float.intBitsToFloat(w.words[base + 2 * w.width * a + i]);
                double max = Float.intBitsToFloat(w.words[base + 2 * w.width * a + w.width + i]);
                double near = r[6 + a] < 0 ? max : min, far = r[6 + a] < 0 ? min : max;
                t0 = Math.max(t0, (near - r[a]) * r[6 + a]);
                t1 = Math.min(t1, (far - r[a]) * r[6 + a]);
            }
            t[i] = t0;
            if (t0 * SHRINK <= t1 * GROW) bits |= 1 << i;
        }
        return bits;
    }

    @Test void theLeafKernelFindsWhatTheTrianglesTestedOneByOneFind() {
        Random rnd = new Random(9);
        for (TriangleMesh mesh : meshes()) {
            Bvh bvh = new BvhBuilder().leafSize(1 + rnd.nextInt(12)).build(mesh);
            double[] corners = bvh.leafCorners(), vertices = mesh.vertices();
            double[] lo = new double[3], hi = new double[3];
            for (int k = 0; k < 3; k++) { lo[k] = bvh.min(0, k); hi[k] = bvh.max(0, k); }
            int[] leaves = java.util.stream.IntStream.range(0, bvh.nodeCount()).filter(n -> bvh.isLeaf(n) && bvh.leafSize(n) > 0).toArray();
            for (int n = 0; n < 20_000; n++) {
                double[] r = ray(rnd, n, lo, hi, vertices);
                int leaf = leaves[rnd.nextInt(leaves.length)], first = bvh.leafStart(leaf), count = bvh.leafSize(leaf);
                if (n % 2 == 0) {   // aim at one of the leaf's triangles' corners or edges
                    int b = 9 * (first + rnd.nextInt(count)), c = rnd.nextInt(3), d = rnd.nextInt(3);
                    double s = rnd.nextInt(3) / 2.0;
                    for (int k = 0; k < 3; k++) {
                        r[3 + k] = corners[b + 3 * c + k] * (1 - s) + corners[b + 3 * d + k] * s - r[k];
                        r[6 + k] = 1 / r[3 + k];
                    }
                    if (!(Double.isFinite(r[6]) && Double.isFinite(r[7]) && Double.isFinite(r[8]))) continue;
                }
                int kz = TriangleIntersector.maxAxis(r[3], r[4], r[5]);
                int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
                if (r[3 + kz] < 0) { int s = kx; kx = ky; ky = s; }
                double sz = r[6 + kz], sx = r[3 + kx] * sz, sy = r[3 + ky] * sz;
                double tMin = n % 4 == 0 ? rnd.nextDouble() : 0, tMax = n % 3 == 0 ? rnd.nextDouble() * 5 : Double.POSITIVE_INFINITY;
                boolean prior = n % 5 == 0;   // a hit found earlier in another leaf
                Hit want = new Hit().reset();
                if (prior) { want.t = tMin + rnd.nextDouble(); want.primitive = rnd.nextInt(bvh.primitiveCount()); }
                double wantT = want.t;
                int wantPrimitive = want.primitive, found = -1;
                for (int p = first; p < first + count; p++)
                    if (TriangleIntersector.test(corners, 9 * p, p, r[kx], r[ky], r[kz], kx, ky, kz, sx, sy, sz, tMin, Math.min(tMax, want.t), want)) found = p;
                for (RayKernel kernel : KERNELS) {
                    LeafBlocks blocks = new LeafBlocks(bvh, corners, kernel.blockWidth());
                    for (boolean any : new boolean[] {false, true}) {
                        Hit got = new Hit().reset();
                        if (prior) { got.t = wantT; got.primitive = wantPrimitive; }
                        int r0 = kernel.hit(blocks.coordinates, blocks.firstBlock, first, count, r[kx], r[ky], r[kz], kx, ky, kz,
                                sx, sy, sz, tMin, prior ? Math.min(tMax, wantT) : tMax, got, any);
                        String what = kernel.getClass().getSimpleName() + (any ? " any" : " closest") + ", leaf of " + count + ", ray " + java.util.Arrays.toString(r);
                        assertThat(r0 >= 0).as(what).isEqualTo(found >= 0);
                        if (any || found < 0) continue;
                        assertThat(r0).as(what).isEqualTo(found);
                        assertThat(got.primitive).as(what).isEqualTo(found);
                        assertThat(Double.doubleToLongBits(got.t)).as(what).isEqualTo(Double.doubleToLongBits(want.t));
                        assertThat(got.u).as(what).isEqualTo(want.u);
                        assertThat(got.v).as(what).isEqualTo(want.v);
                    }
                }
            }
        }
    }
}
