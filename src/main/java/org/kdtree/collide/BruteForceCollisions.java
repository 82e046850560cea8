package org.kdtree.collide;

/**
 * The sphere queries answered by testing every primitive: the oracle the tree queries are checked
 * against, and the baseline whose cost ({@code size()} tests per query) they save. Same exact
 * tests, same tie rule (the smallest index among equally early contacts).
 */
final class BruteForceCollisions {
    private final Collider prims;

    /** @param prims the primitives and their exact tests */
    public BruteForceCollisions(Collider prims) {
        this.prims = prims;
    }

    /**
     * As {@link OverlapQuery#overlapping}: the primitives within r of {@code centre}, in index order.
     *
     * @param centre the sphere's centre
     * @param r      its radius, finite and at least 0
     * @param out    receives the first {@code out.length} of them
     * @return how many there are, even when more than {@code out.length}
     */
    public int overlapping(double[] centre, double r, int[] out) {
        SphereQueries.checkPoint("centre", centre, prims.dimension());
        SphereQueries.checkRadius(r);
        int count = 0;
        for (int p = 0; p < prims.size(); p++) {
            if (prims.closestPoint(p, centre, null) <= r * r) {
                if (count < out.length) out[count] = p;
                count++;
            }
        }
        return count;
    }

    /**
     * As {@link SweepQuery#firstContact}: the first contact of a sphere moving from {@code s} to
     * {@code s + d}.
     *
     * @param s       the centre at the start
     * @param d       the motion
     * @param r       the radius, finite and at least 0
     * @param contact filled with the contact, or reset when there is none
     * @return whether the sphere touches anything on the way
     */
    public boolean firstContact(double[] s, double[] d, double r, Contact contact) {
        SphereQueries.checkPoint("start", s, prims.dimension());
        SphereQueries.checkPoint("motion", d, prims.dimension());
        SphereQueries.checkRadius(r);
        contact.reset();
        int best = -1;
        double bestT = 1;
        for (int p = 0; p < prims.size(); p++) {
            double t = prims.firstContact(p, s, d, r, bestT);
            if (t <= bestT && (best < 0 || t < bestT)) { bestT = t; best = p; }
        }
        if (best >= 0) contact.complete(prims, best, bestT, s, d);
        return best >= 0;
    }
}
