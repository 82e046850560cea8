package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.kdtree.collide.ShapeCollider;
import org.kdtree.generate.Shapes;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.spec.Builders;

/** Balls dropped into a walled 2-D scene stay out of its objects, do not gain energy, and the tree saves tests. */
class BallSimulationTest {
    @Test void ballsStayOutOfTheSceneAndDoNotGainEnergy() {
        List<Shape2D> shapes = new ArrayList<>(Shapes.mixed(120, 9).shapes());
        shapes.add(new Shape2D.Rect(-10, -10, 110, -5));  // floor
        shapes.add(new Shape2D.Rect(-10, -10, -5, 130));  // walls
        shapes.add(new Shape2D.Rect(105, -10, 110, 130));
        shapes.add(new Shape2D.Rect(-10, 125, 110, 130)); // ceiling
        Scene2D scene = new Scene2D(shapes);
        KdTree tree = Builders.create("sah").build(scene);
        ShapeCollider objects = new ShapeCollider(scene);
        double restitution = 0.8;
        BallSimulation sim = new BallSimulation(tree, scene, 40, 0, -9.81, restitution);
        Random rnd = new Random(4);
        while (sim.balls() < 40) {
            double[] p = {rnd.nextDouble() * 100, 60 + rnd.nextDouble() * 60};
            double r = 0.5 + rnd.nextDouble() * 1.5;
            if (overlapping(objects, p, r) == 0) sim.addBall(p[0], p[1], rnd.nextGaussian() * 5, 0, r);
        }
        double tolerance = 1e-6;
        double energy = sim.energy(), start = energy;
        long tests = 0, bruteTests = 0;
        for (int step = 0; step < 300; step++) {
            sim.step(0.02);
            tests += sim.lastTests();
            bruteTests += sim.lastBruteForceTests();
            for (int b = 0; b < sim.balls(); b++) {
                double[] c = {sim.x(b), sim.y(b)};
                assertThat(overlapping(objects, c, sim.radius(b) - tolerance)).as("step " + step + " ball " + b + " at "
                        + c[0] + ", " + c[1]).isZero();
            }
            double now = sim.energy();
            // Each contact may lift a ball by the skin: allow that, nothing more.
            assertThat(now).as("energy at step " + step).isLessThanOrEqualTo(energy + 1e-9 * Math.abs(energy) + 1e-6);
            energy = now;
        }
        assertThat(energy).as("bounces with restitution 0.8 lost energy").isLessThan(start - 100);
        assertThat(tests).as("tree tests %d vs brute force %d", tests, bruteTests).isLessThan(bruteTests / 5);
    }

    @Test void placeMovesABallAndKeepsItsRadius() {
        Scene2D scene = new Scene2D(List.of(new Shape2D.Segment(0, 0, 10, 0)));
        BallSimulation sim = new BallSimulation(Builders.create("sah").build(scene), scene, 2, 0, -10, 0.5);
        sim.addBall(1, 5, 0, 0, 0.25);
        sim.place(0, 3, 7, 1, -2);
        assertThat(new double[] {sim.x(0), sim.y(0), sim.vx(0), sim.vy(0), sim.radius(0)}).containsExactly(3, 7, 1, -2, 0.25);
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> sim.place(1, 0, 0, 0, 0))
                .isInstanceOf(IndexOutOfBoundsException.class).hasMessage("ball 1 of 1");
    }

    /** Brute force, the oracle: how many objects a disc of radius {@code r} at {@code c} overlaps. */
    private static int overlapping(ShapeCollider shapes, double[] c, double r) {
        int n = 0;
        for (int i = 0; i < shapes.size(); i++) if (shapes.closestPoint(i, c, null) <= r * r) n++;
        return n;
    }
}
