package org.kdtree.shape;

import org.kdtree.geom.Box;

/**
 * The only view a builder has of the geometry: a numbered set of primitives in k dimensions.
 *
 * <p>Implementations write into destination boxes so that builders allocate nothing per
 * query, and must be safe for concurrent reads (a parallel build queries from many threads).
 */
public interface Primitives {
    /** {@return k, the dimension of the space} */
    int dimension();

    /** {@return the number of primitives}; they are numbered {@code 0 .. size()-1}. */
    int size();

    /**
     * Writes the bounds of primitive {@code i} into {@code dest}.
     *
     * @param i the primitive's index
     * @param dest receives its bounds
     */
    void bounds(int i, Box dest);

    /**
     * Writes the bounds of the part of primitive {@code i} inside {@code voxel} into
     * {@code dest} ("perfect splits"), or makes {@code dest} empty if no part is inside.
     * The bounds may be conservative by a few units in the last place, never smaller.
     * @param i the primitive's index
     * @param voxel the voxel to clip to
     * @param dest receives the clipped bounds
     */
    void clip(int i, Box voxel, Box dest);

    /**
     * The clipped bounds of primitive {@code i} in both children of {@code voxel} split by the
     * plane {@code x_axis = xi}: the part below into {@code left}, the part above into
     * {@code right}, each set empty when there is none. Builders call this for the primitives
     * that straddle a split. The default clips to each half; an implementation may share the
     * work (clip to the voxel once, then cut by the plane), as long as the results are
     * conservative in the sense of {@link #clip}.
     * @param i the primitive's index
     * @param voxel the voxel being split
     * @param axis the split plane's axis
     * @param xi the split plane's position
     * @param left receives the bounds of the part below the plane
     * @param right receives the bounds of the part above the plane
     */
    default void clipSplit(int i, Box voxel, int axis, double xi, Box left, Box right) {
        clip(i, voxel.lowerPart(axis, xi), left);
        clip(i, voxel.upperPart(axis, xi), right);
    }

    /**
     * {@return a short description of primitive {@code i} for error messages}, e.g. "triangle 17".
     *
     * @param i the primitive's index
     */
    default String describe(int i) {
        return "primitive " + i;
    }

    /** {@return the bounds of all primitives} (an empty box when there are none). */
    default Box bounds() {
        Box all = new Box(dimension());
        Box b = new Box(dimension());
        for (int i = 0; i < size(); i++) {
            bounds(i, b);
            all.grow(b);
        }
        return all;
    }
}
