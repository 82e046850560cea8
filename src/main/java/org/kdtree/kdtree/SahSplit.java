package org.kdtree.kdtree;

import org.kdtree.geom.SplitPlane;

/**
 * The best plane a search found and its SAH cost. Searches keep the first minimum they meet
 * in the order axis 0, 1, ..., then increasing position, then planar-left before planar-right,
 * so that every algorithm picks the same plane among equal costs.
 */
final class SahSplit {
    private int axis = -1;
    private double position;
    private boolean planarLeft;
    private double cost = Double.POSITIVE_INFINITY;

    /**
     * Offers the plane {@code x_axis = x} with {@code nl} primitives strictly left, {@code nr}
     * strictly right and {@code np} lying in the plane; the planar ones go to the cheaper side.
     * @param sah the cost of the voxel being split
     * @param axis the plane's axis
     * @param x its position
     * @param nl primitives strictly left
     * @param np primitives in the plane
     * @param nr primitives strictly right
     */
    public void offer(SahCost sah, int axis, double x, int nl, int np, int nr) {
        if (!sah.inside(axis, x)) return;
        double left = sah.cost(axis, x, nl + np, nr);
        double right = np == 0 ? left : sah.cost(axis, x, nl, nr + np);
        boolean toLeft = left <= right;
        double c = toLeft ? left : right;
        if (c < cost) {
            cost = c;
            this.axis = axis;
            position = x;
            planarLeft = toLeft;
        }
    }

    /** Forgets the plane, to search another node with the same object. */
    void reset() {
        axis = -1;
        cost = Double.POSITIVE_INFINITY;
    }

    int axis() { return axis; }

    double position() { return position; }

    boolean planarLeft() { return planarLeft; }

    /** {@return true once some candidate has been offered} */
    public boolean found() { return axis >= 0; }

    /** {@return the SAH cost of the best plane}, infinite until one is offered. */
    public double cost() { return cost; }

    /** {@return the plane}; call only when {@link #found()}. */
    public SplitPlane plane() { return new SplitPlane(axis, position, planarLeft); }

    @Override public String toString() {
        return found() ? "SahSplit[" + plane() + ", cost=" + cost + "]" : "SahSplit[none]";
    }
}
