package org.kdtree.kdtree;

import org.kdtree.accel.Hit;
import org.kdtree.accel.RayPacket;
import org.kdtree.accel.TriangleIntersector;

/**
 * A packet's rays as lanes, what {@link PacketTraversal}'s loop and its kernels ({@link
 * PacketKernel}) share: per lane (a ray of the packet, index 0 to {@link #N} - 1) its origin and
 * inverse direction, its interval at the current node, the watertight test's shear and its closest
 * hit so far, in arrays made once. A set of lanes is a {@code long} with bit i for lane i.
 */
final class PacketLanes {
    /** Lanes: a packet's rays, one bit each of a {@code long} mask. */
    static final int N = RayPacket.CAPACITY;

    static {
        if (N > Long.SIZE) throw new AssertionError("a lane mask is a long: at most 64 rays a packet");
    }

    /** Per axis, per lane: origin and inverse direction. */
    final double[][] origin = new double[3][N], inverse = new double[3][N];
    /** Per lane: its interval {@code [tMin, tMax]} as the caller gave it. */
    final double[] tMin = new double[N], tMax = new double[N];
    /** Per lane: its interval at the current node and that interval widened by the slack (the single-ray loop's lo and hi). */
    final double[] curMin = new double[N], curMax = new double[N], lo = new double[N], hi = new double[N];
    /** Per lane: the watertight test's axes (z the direction's largest component) and shear ({@link MeshTraversal}'s). */
    final int[] kx = new int[N], ky = new int[N], kz = new int[N];
    /** Per lane: origin on the shear's axes, and the shear itself. */
    final double[] okx = new double[N], oky = new double[N], okz = new double[N], sx = new double[N], sy = new double[N], sz = new double[N];
    /** The lanes whose shear axis x (y, z) is axis 1, and those where it is axis 2: {@link #kx} as masks, for lanes that select. */
    long xIs1, xIs2, yIs1, yIs2, zIs1, zIs2;
    /** Per lane: its closest hit's primitive so far (-1: none), as a double (exact for every int) so that vector lanes of doubles compare it. */
    final double[] bestPrim = new double[N];
    /** Per lane: t and barycentrics of its closest hit so far (t +infinity: none). */
    final double[] bestT = new double[N], bestU = new double[N], bestV = new double[N];
    /** One lane's closest hit while the Java 17 leaf kernel tests its triangles ({@link TriangleIntersector#test} records there). */
    final Hit laneHit = new Hit();
    /** What the node kernel found: the lanes that go to the near child, and those that go to the far one (both: in each). */
    long toNear, toFar;

    /**
     * Puts ray {@code i} of {@code p} in lane {@code i}: its origin, inverse direction and interval,
     * no hit yet, and the watertight test's shear as {@link MeshTraversal} computes it once per ray.
     * (Its interval at the nodes is the loop's to set; the masks of shear axes are cleared first, {@link #clearAxes}.)
     */
    void load(RayPacket p, int i) {
        double dx = p.dx[i], dy = p.dy[i], dz = p.dz[i];
        origin[0][i] = p.ox[i]; origin[1][i] = p.oy[i]; origin[2][i] = p.oz[i];
        inverse[0][i] = p.ix[i]; inverse[1][i] = p.iy[i]; inverse[2][i] = p.iz[i];
        tMin[i] = p.tMin[i];
        tMax[i] = p.tMax[i];
        bestPrim[i] = -1;
        bestT[i] = Double.POSITIVE_INFINITY;
        bestU[i] = bestV[i] = 0;
        int z = TriangleIntersector.maxAxis(dx, dy, dz);
        int x = z == 2 ? 0 : z + 1, y = x == 2 ? 0 : x + 1;
        double dz0 = z == 0 ? dx : z == 1 ? dy : dz;
        if (dz0 < 0) { int s = x; x = y; y = s; }
        double s = inverse[z][i];
        shearAxes(i, x, y, z);
        sz[i] = s;
        sx[i] = (x == 0 ? dx : x == 1 ? dy : dz) * s;
        sy[i] = (y == 0 ? dx : y == 1 ? dy : dz) * s;
        okx[i] = origin[x][i];
        oky[i] = origin[y][i];
        okz[i] = origin[z][i];
    }

    /** Sets lane {@code i}'s shear axes and their bits in the masks ({@link #xIs1} and the others; {@link #clearAxes} first). */
    private void shearAxes(int i, int x, int y, int z) {
        kx[i] = x;
        ky[i] = y;
        kz[i] = z;
        xIs1 |= (long) (x & 1) << i;                     // an axis is 0, 1 or 2: bit 0 says 1, bit 1 says 2
        xIs2 |= (long) (x >> 1) << i;
        yIs1 |= (long) (y & 1) << i;
        yIs2 |= (long) (y >> 1) << i;
        zIs1 |= (long) (z & 1) << i;
        zIs2 |= (long) (z >> 1) << i;
    }

    /** Clears the shear axes' masks, before a packet's lanes are loaded. */
    void clearAxes() {
        xIs1 = xIs2 = yIs1 = yIs2 = zIs1 = zIs2 = 0;
    }
}
