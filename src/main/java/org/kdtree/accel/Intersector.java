package org.kdtree.accel;

import org.kdtree.geom.Ray;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.TriangleMesh;

/**
 * Ray tests against numbered primitives: what the traversal adds to the builders' view.
 * Implementations must be safe for concurrent use and allocate nothing per call.
 */
public interface Intersector {
    /**
     * The ray tests of {@code primitives}: what a structure built over them binds once, so that
     * its queries trace exactly the primitives it was built over.
     *
     * @param primitives a triangle mesh or a 2-D scene
     * @return a {@link TriangleIntersector} or a {@link Shape2DIntersector}
     * @throws IllegalArgumentException for primitives no ray can be traced against (points)
     */
    static Intersector of(Primitives primitives) {
        return of(primitives, TriangleIntersector.cornersOf(primitives));
    }

    /**
     * {@link #of(Primitives)}, over a mesh's corners already made by {@link TriangleIntersector#cornersOf}:
     * a structure that also reads them in its own hot loop keeps one copy.
     *
     * @param primitives a triangle mesh or a 2-D scene
     * @param corners    {@code TriangleIntersector.cornersOf(primitives)}: null unless a mesh
     * @return the ray tests
     * @throws IllegalArgumentException for primitives no ray can be traced against (points)
     */
    static Intersector of(Primitives primitives, double[] corners) {
        if (corners != null) return new TriangleIntersector(corners);
        if (primitives instanceof Scene2D scene) return new Shape2DIntersector(scene);
        throw new IllegalArgumentException("rays are traced against triangles or 2-D shapes, not " + primitives.getClass().getSimpleName()
                + " (points answer nearest-neighbour and range queries: points.PointTree)");
    }

    /** {@return k, the dimension} */
    int dimension();

    /** {@return the number of primitives} */
    int size();

    /**
     * Tests primitive {@code i}. If the ray meets it at a parameter t with
     * {@code tMin <= t <= tMax} and {@code t < hit.t}, records primitive, t and hit data in
     * {@code hit} and returns true; otherwise leaves {@code hit} untouched and returns false.
     * A ray meeting a primitive exactly on an edge or vertex hits it; degenerate primitives
     * are never hit.
     * @param i the primitive's index
     * @param ray the ray
     * @param tMin the start of the ray's range
     * @param tMax the end of the ray's range
     * @param hit the closest hit so far; updated on a closer hit
     * @return whether a closer hit was recorded
     */
    boolean intersect(int i, Ray ray, double tMin, double tMax, Hit hit);
}
