package org.kdtree.geom;

/**
 * Doubles rounded to floats outwards, so that a box held in floats contains the double box it
 * came from: a minimum rounded down, a maximum up (the float bounds of the BVH and of the
 * binned kd-tree build; nothing is lost, a box only grows by less than a float's ulp).
 */
public final class OutwardFloat {
    private OutwardFloat() {
    }

    /**
     * {@return the largest float at most {@code v}}
     * @param v a finite double (or an infinity)
     */
    public static float down(double v) {
        float f = (float) v;
        return f > v ? Math.nextDown(f) : f;
    }

    /**
     * {@return the smallest float at least {@code v}}
     * @param v a finite double (or an infinity)
     */
    public static float up(double v) {
        float f = (float) v;
        return f < v ? Math.nextUp(f) : f;
    }
}
