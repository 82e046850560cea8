package org.kdtree.accel;

/**
 * Up to {@link #CAPACITY} rays traced together, and their closest hits: structure-of-arrays,
 * reused between packets (a renderer's tile of camera rays, a block of the benchmark's primary
 * rays). A {@link PacketQuery} fills {@link #primitive}, {@link #t}, {@link #u} and {@link #v}
 * for each ray exactly as {@link RayQuery#closestHit} answers that ray alone.
 */
public final class RayPacket {
    /** The most rays a packet holds: an 8 x 8 tile. */
    public static final int CAPACITY = 64;

    /** The rays' origins, directions and 1 / direction, per axis. */
    public final double[] ox = new double[CAPACITY], oy = new double[CAPACITY], oz = new double[CAPACITY],
            dx = new double[CAPACITY], dy = new double[CAPACITY], dz = new double[CAPACITY],
            ix = new double[CAPACITY], iy = new double[CAPACITY], iz = new double[CAPACITY];
    /** The rays' intervals of t. */
    public final double[] tMin = new double[CAPACITY], tMax = new double[CAPACITY];
    /** Each ray's closest hit: the primitive (-1 for none), t (+infinity for none) and barycentrics (as {@link Hit}). */
    public final int[] primitive = new int[CAPACITY];
    /** See {@link #primitive}. */
    public final double[] t = new double[CAPACITY], u = new double[CAPACITY], v = new double[CAPACITY];
    private int size;

    /** The edge of the square tile whose pixels {@link #tileOrder} puts in Morton order: 8, a full packet. */
    public static final int TILE = 8;

    /**
     * The pixels of a block {@code w} wide and {@code h} high, as indices {@code y * stride + x}
     * (row by row in an image {@code stride} wide), in the order to fill a packet with them: Morton (Z) order when the block
     * fits an 8 x 8 tile, so that a packet's first 4, 8, 16 rays are 2 x 2, 4 x 2 and 4 x 4 squares
     * and each group of vector lanes covers a compact patch of the image, not a row (measured: 1.17 x
     * the speed of rows on the bunny's set P, 1.25 x on its 4 x 4 grid); row by row otherwise.
     *
     * @param w      the block's width, at least 1
     * @param h      its height, at least 1, with {@code w * h <= order.length}
     * @param stride the width of the image the indices count in, at least {@code w}
     * @param order  receives the {@code w * h} indices
     * @return {@code w * h}
     */
    public static int tileOrder(int w, int h, int stride, int[] order) {
        int n = 0;
        if (w <= TILE && h <= TILE) {
            for (int m = 0; m < TILE * TILE; m++) {
                int x = (m & 1) | (m >> 1 & 2) | (m >> 2 & 4), y = (m >> 1 & 1) | (m >> 2 & 2) | (m >> 3 & 4);
                if (x < w && y < h) order[n++] = y * stride + x;
            }
        } else {
            for (int y = 0; y < h; y++) for (int x = 0; x < w; x++) order[n++] = y * stride + x;
        }
        return n;
    }

    /** {@return how many rays it holds} */
    public int size() { return size; }

    /**
     * Empties it.
     *
     * @return this packet
     */
    public RayPacket clear() {
        size = 0;
        return this;
    }

    /**
     * Adds a 3-D ray.
     *
     * @param ox   origin x
     * @param oy   origin y
     * @param oz   origin z
     * @param dx   direction x
     * @param dy   direction y
     * @param dz   direction z
     * @param tMin the start of its interval
     * @param tMax its end
     * @return the ray's index in the packet
     * @throws IllegalStateException if the packet is full
     */
    public int add(double ox, double oy, double oz, double dx, double dy, double dz, double tMin, double tMax) {
        if (size == CAPACITY) throw new IllegalStateException("a packet holds " + CAPACITY + " rays");
        int i = size++;
        this.ox[i] = ox; this.oy[i] = oy; this.oz[i] = oz;
        this.dx[i] = dx; this.dy[i] = dy; this.dz[i] = dz;
        ix[i] = 1.0 / dx; iy[i] = 1.0 / dy; iz[i] = 1.0 / dz;     // as Ray.set
        this.tMin[i] = tMin;
        this.tMax[i] = tMax;
        return i;
    }

    /**
     * {@return the octant of direction (dx, dy, dz)}: bits 0, 1 and 2 set where x, y and z are
     * negative; -1 when a component's inverse is not finite (zero, subnormal, NaN), a direction the
     * packet loops, which need one sign per axis, leave to single rays. Rays gathered by octant fill
     * packets the loops trace whole.
     *
     * @param dx direction x
     * @param dy direction y
     * @param dz direction z
     */
    public static int octant(double dx, double dy, double dz) {
        return octantOfInverse(1.0 / dx, 1.0 / dy, 1.0 / dz);
    }

    /**
     * {@return ray {@code i}'s octant of directions}, as {@link #octant(double, double, double)}
     * gives it from its stored inverse direction
     *
     * @param i a ray's index
     */
    public int octant(int i) {
        return octantOfInverse(ix[i], iy[i], iz[i]);
    }

    private static int octantOfInverse(double ix, double iy, double iz) {
        if (ix - ix != 0 || iy - iy != 0 || iz - iz != 0) return -1;
        return (ix < 0 ? 1 : 0) | (iy < 0 ? 2 : 0) | (iz < 0 ? 4 : 0);
    }

    /**
     * {@return whether ray {@code i} hit}
     *
     * @param i a ray's index
     */
    public boolean found(int i) { return primitive[i] >= 0; }

    /**
     * Copies ray {@code i} into {@code ray}.
     *
     * @param i   a ray's index
     * @param ray a 3-D ray, overwritten
     * @return {@code ray}
     */
    public org.kdtree.geom.Ray ray(int i, org.kdtree.geom.Ray ray) {
        return ray.set(ox[i], oy[i], oz[i], dx[i], dy[i], dz[i]);
    }

    /**
     * Records ray {@code i}'s answer from a single-ray query's hit.
     *
     * @param i   a ray's index
     * @param hit its closest hit, or none
     */
    public void record(int i, Hit hit) {
        record(i, hit.primitive, hit.t, hit.u, hit.v);
    }

    /**
     * Records ray {@code i}'s hit: what a packet loop found for it.
     *
     * @param i         a ray's index
     * @param primitive the primitive hit
     * @param t         where along the ray
     * @param u         the hit's first barycentric coordinate
     * @param v         its second
     */
    public void record(int i, int primitive, double t, double u, double v) {
        this.primitive[i] = primitive;
        this.t[i] = t;
        this.u[i] = u;
        this.v[i] = v;
    }

    /**
     * Records that ray {@code i} hits nothing: primitive -1, t infinite, barycentrics 0, as a
     * single-ray query's {@link Hit#reset} leaves it.
     *
     * @param i a ray's index
     */
    public void recordMiss(int i) {
        record(i, -1, Double.POSITIVE_INFINITY, 0, 0);
    }

    /**
     * Records whether ray {@code i} is blocked, from a single-ray any-hit query ({@link PacketQuery#anyHits}):
     * no hit as {@link #recordMiss} writes it, or a hit on an unnamed primitive (index 0, t and barycentrics 0).
     *
     * @param i       a ray's index
     * @param blocked whether the ray hits anything in its interval
     */
    public void recordAny(int i, boolean blocked) {
        if (blocked) record(i, 0, 0, 0, 0);
        else recordMiss(i);
    }
}
