package org.kdtree.gui;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.kdtree.collide.ShapeCollider;
import org.kdtree.shape.Scene2D;

/** The oracle of the nearest-neighbour stepper: every object's exact distance, sorted by (distance, index). */
final class NearestBruteForce {
    private NearestBruteForce() {
    }

    /** The k objects nearest to {@code q}, nearest first; zero-area shapes (infinitely far) left out. */
    static List<NearestTrace.Neighbour> nearest(Scene2D scene, double[] q, int k) {
        ShapeCollider c = new ShapeCollider(scene);
        List<double[]> all = new ArrayList<>();
        for (int i = 0; i < scene.size(); i++) {
            double ds = c.closestPoint(i, q, null);
            if (ds < Double.POSITIVE_INFINITY) all.add(new double[] {ds, i});
        }
        all.sort(Comparator.<double[]>comparingDouble(a -> a[0]).thenComparingDouble(a -> a[1]));
        return all.stream().limit(k).map(a -> new NearestTrace.Neighbour((int) a[1], Math.sqrt(a[0]))).toList();
    }
}
