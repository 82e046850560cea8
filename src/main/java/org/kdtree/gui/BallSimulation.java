package org.kdtree.gui;

import org.kdtree.collide.Contact;
import org.kdtree.collide.ShapeCollider;
import org.kdtree.collide.SweepQuery;
import org.kdtree.geom.Tolerance;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.Scene2D;

/**
 * The talk's figure of balls bouncing in a fixed scene, headless: N balls fall under gravity in a
 * 2-D scene ({@link Scene2D}) and bounce off its objects (not off each other). Each step moves
 * each ball with its swept query ({@link SweepQuery}): up to the first contact, reflect the velocity
 * about the contact normal (scaled by the restitution), go on with what is left of the step, up to
 * {@link #MAX_BOUNCES} contacts per ball and step.
 *
 * <p>A ball stopped at a contact is set a hair ({@link #skin}) off the surface along the normal, so
 * that its next sweep does not start touching the same object and stick there. Velocities use
 * semi-implicit Euler (velocity first), which does not gain energy under constant gravity; a bounce
 * with restitution {@code <= 1} does not either. Per step it counts the primitive tests the tree needed
 * and what brute force would have needed (every primitive per sweep). Allocation-free per step.
 */
final class BallSimulation {
    /** Contacts handled per ball and step; the rest of the step is dropped (a ball wedged in a corner). */
    public static final int MAX_BOUNCES = 4;

    private final SweepQuery sweep;
    private final int primitives;
    private final double gx, gy, restitution, skin;
    private final double[] x, y, vx, vy, r;
    private int n;
    private long tests, bruteTests;
    private final double[] s = new double[2], d = new double[2];
    private final Contact contact = new Contact();

    /**
     * @param tree        a tree over {@code scene}
     * @param scene       the static objects
     * @param capacity    the most balls
     * @param gx          gravity, x
     * @param gy          gravity, y
     * @param restitution 0 (no bounce) to 1 (elastic)
     */
    public BallSimulation(KdTree tree, Scene2D scene, int capacity, double gx, double gy, double restitution) {
        if (!(restitution >= 0 && restitution <= 1)) throw new IllegalArgumentException("restitution must be in [0, 1]: " + restitution);
        sweep = new SweepQuery(tree, new ShapeCollider(scene));
        primitives = scene.size();
        this.gx = gx;
        this.gy = gy;
        this.restitution = restitution;
        double extent = Math.max(1, tree.bounds().magnitude());
        skin = extent * Tolerance.CONTACT_SKIN;
        x = new double[capacity];
        y = new double[capacity];
        vx = new double[capacity];
        vy = new double[capacity];
        r = new double[capacity];
    }

    /**
     * Adds a ball.
     *
     * @param px     the centre's start, x
     * @param py     the centre's start, y
     * @param velX   the start velocity, x
     * @param velY   the start velocity, y
     * @param radius the ball's radius
     * @return its index: 0 for the first ball added, then 1, 2, ...
     * @throws IllegalStateException when {@code capacity} balls were added already
     */
    public int addBall(double px, double py, double velX, double velY, double radius) {
        if (n == x.length) throw new IllegalStateException("capacity " + x.length + " reached");
        x[n] = px; y[n] = py; vx[n] = velX; vy[n] = velY; r[n] = radius;
        return n++;
    }

    /**
     * Puts ball {@code b} at (px, py) with velocity (velX, velY), its radius kept: for instance to
     * drop a ball that has left the scene again from above.
     *
     * @param b    the ball's number, {@code 0 .. balls() - 1}
     * @param px   the new centre's x
     * @param py   the new centre's y
     * @param velX the new velocity's x
     * @param velY the new velocity's y
     */
    public void place(int b, double px, double py, double velX, double velY) {
        if (b < 0 || b >= n) throw new IndexOutOfBoundsException("ball " + b + " of " + n);
        x[b] = px; y[b] = py; vx[b] = velX; vy[b] = velY;
    }

    /**
     * Advances every ball by {@code dt}, and counts this step's primitive tests.
     *
     * @param dt the step's duration
     */
    public void step(double dt) {
        tests = bruteTests = 0;
        for (int b = 0; b < n; b++) move(b, dt);
    }

    private void move(int b, double dt) {
        vx[b] += gx * dt;
        vy[b] += gy * dt;
        double left = dt; // time still to move in this step
        for (int bounce = 0; bounce < MAX_BOUNCES && left > 0; bounce++) {
            s[0] = x[b]; s[1] = y[b];
            d[0] = vx[b] * left; d[1] = vy[b] * left;
            boolean hit = sweep.firstContact(s, d, r[b], contact);
            tests += sweep.lastTests();
            bruteTests += primitives;
            if (!hit) {
                x[b] += d[0];
                y[b] += d[1];
                return;
            }
            double nx = contact.normal[0], ny = contact.normal[1];
            x[b] = contact.centre[0] + nx * skin;
            y[b] = contact.centre[1] + ny * skin;
            double vn = vx[b] * nx + vy[b] * ny;
            if (vn < 0) { // coming in: reflect the normal part, scaled by the restitution
                vx[b] -= (1 + restitution) * vn * nx;
                vy[b] -= (1 + restitution) * vn * ny;
            }
            left *= 1 - contact.t;
        }
    }

    /** {@return the number of balls added} */
    public int balls() { return n; }

    /**
     * {@return ball {@code b}'s centre, x}
     * @param b the ball's index, from {@link #addBall}
     */
    public double x(int b) { return x[b]; }

    /**
     * {@return ball {@code b}'s centre, y}
     * @param b the ball's index, from {@link #addBall}
     */
    public double y(int b) { return y[b]; }

    /**
     * {@return ball {@code b}'s velocity, x}
     * @param b the ball's index, from {@link #addBall}
     */
    public double vx(int b) { return vx[b]; }

    /**
     * {@return ball {@code b}'s velocity, y}
     * @param b the ball's index, from {@link #addBall}
     */
    public double vy(int b) { return vy[b]; }

    /**
     * {@return ball {@code b}'s radius}
     * @param b the ball's index, from {@link #addBall}
     */
    public double radius(int b) { return r[b]; }

    /** {@return the kinetic plus potential energy of all balls} Unit masses; potential 0 at the origin. */
    public double energy() {
        double e = 0;
        for (int b = 0; b < n; b++) e += 0.5 * (vx[b] * vx[b] + vy[b] * vy[b]) - (gx * x[b] + gy * y[b]);
        return e;
    }

    /** {@return the primitive tests the tree needed in the last step} */
    public long lastTests() { return tests; }

    /** {@return the primitive tests brute force would have needed in the last step} Every primitive per sweep. */
    public long lastBruteForceTests() { return bruteTests; }

    /** {@return how far off a surface a ball stopped at a contact is set} */
    public double skin() { return skin; }
}
