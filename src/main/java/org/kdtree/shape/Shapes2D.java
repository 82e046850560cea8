package org.kdtree.shape;

import java.util.List;
import org.kdtree.geom.Box;

/** A 2-D scene of points, segments, rectangles and triangles, as the workbench edits it. */
public final class Shapes2D implements Primitives {
    private final List<Shape2D> shapes;

    /**
     * Wraps a copy of the list; rejects NaN or infinite coordinates, naming the shape.
     *
     * @param shapes the shapes, primitive i being the i-th
     * @throws InvalidGeometryException for a non-finite coordinate
     */
    public Shapes2D(List<? extends Shape2D> shapes) {
        this.shapes = List.copyOf(shapes);
        for (int i = 0; i < this.shapes.size(); i++) {
            for (double c : this.shapes.get(i).coords()) {
                if (!Double.isFinite(c))
                    throw new InvalidGeometryException(describe(i) + " has a non-finite coordinate (" + c + ")");
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
