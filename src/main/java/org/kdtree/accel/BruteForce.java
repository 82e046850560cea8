package org.kdtree.accel;

import org.kdtree.geom.Ray;

/** Every query answered by testing every primitive: the oracle that the kd-tree must agree with. */
public final class BruteForce implements RayQuery {
    private final Intersector prims;

    /** @param prims the primitives and their exact ray tests */
    public BruteForce(Intersector prims) {
        this.prims = prims;
    }

    @Override public boolean closestHit(Ray ray, double tMin, double tMax, Hit hit) {
        hit.reset();
        for (int i = 0; i < prims.size(); i++) prims.intersect(i, ray, tMin, tMax, hit);
        return hit.found();
    }

    @Override public boolean anyHit(Ray ray, double tMin, double tMax) {
        Hit hit = new Hit();
        for (int i = 0; i < prims.size(); i++) if (prims.intersect(i, ray, tMin, tMax, hit)) return true;
        return false;
    }
}
