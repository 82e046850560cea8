package org.kdtree.shape;

import org.kdtree.geom.Tolerance;
import java.util.List;
import org.kdtree.geom.Box;

/** A 2-D scene of points, segments, rectangles and triangles, as the workbench edits it. */
public final class Scene2D implements Primitives {
    private final List<Shape2D> shapes;

    /**
     * Wraps a copy of the list; rejects NaN or infinite coordinates, naming the shape.
     *
     * @param shapes the shapes, primitive i being the i-th
     * @throws InvalidGeometryException for a non-finite coordinate, or one beyond
     *         {@link Tolerance#MAX_COORDINATE} (the ray and circle tests' products would overflow)
     */
    public Scene2D(List<? extends Shape2D> shapes) {
        this.shapes = List.copyOf(shapes);
        for (int i = 0; i < this.shapes.size(); i++) {
            for (double c : this.shapes.get(i).coords()) {
                if (!Double.isFinite(c))
                    throw new InvalidGeometryException(describe(i) + " has a non-finite coordinate (" + c + ")");
                if (Math.abs(c) > Tolerance.MAX_COORDINATE)
                    throw new InvalidGeometryException(describe(i) + " has the coordinate " + c
                            + ": the supported range is -1e100 .. 1e100 (the ray and circle tests would overflow); scale the scene down");
            }
        }
    }

    /**
     * {@return shape {@code i}}
     *
     * @param i the primitive's index
     */
    public Shape2D get(int i) { return shapes.get(i); }
    /** {@return the shapes, unmodifiable} */
    public List<Shape2D> shapes() { return shapes; }

    @Override public int dimension() { return 2; }
    @Override public int size() { return shapes.size(); }
    @Override public void bounds(int i, Box dest) { shapes.get(i).bounds(dest); }
    @Override public void clip(int i, Box voxel, Box dest) { shapes.get(i).clip(voxel, dest); }

    @Override public String describe(int i) {
        return shapes.get(i).keyword() + " " + i;
    }
}
