package org.kdtree.kdtree;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.check.Contract;
import org.kdtree.spec.Builders;

/**
 * Zero-area objects (collinear triangles, flat rectangles) have empty clipped bounds in most
 * voxels, so a split can send some node's every object to neither child. Every builder must
 * still end with a sound tree (that node a leaf; every invariant the contract checks holds), never
 * an arithmetic error.
 */
class DegenerateObjectsTest {
    private static double c(Random r) {
        return r.nextInt(9) / 2.0;
    }

    @Test void everyBuilderBuildsScenesOfZeroAreaObjects() {
        Random r = new Random(11);
        for (int scene = 0; scene < 1500; scene++) {
            List<Shape2D> shapes = new ArrayList<>();
            for (int i = 0; i < 1 + r.nextInt(30); i++) {   // on a coarse grid: many shapes are flat, collinear or points
                shapes.add(switch (r.nextInt(4)) {
                    case 0 -> new Shape2D.Triangle(c(r), c(r), c(r), c(r), c(r), c(r));
                    case 1 -> new Shape2D.Rect(c(r), c(r), c(r), c(r));
                    case 2 -> new Shape2D.Segment(c(r), c(r), c(r), c(r));
                    default -> new Shape2D.Point(c(r), c(r));
                });
            }
            Scene2D s = new Scene2D(shapes);
            for (String name : Builders.names())   // a tree every invariant of which holds, or a named violation
                Contract.check(Builders.create(name), s, "zero-area scene " + scene);
        }
    }
}
