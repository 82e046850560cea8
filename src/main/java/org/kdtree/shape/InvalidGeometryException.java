package org.kdtree.shape;

/** Thrown for geometry that no builder can accept, e.g. a NaN or infinite coordinate. */
public class InvalidGeometryException extends IllegalArgumentException {
    public InvalidGeometryException(String message) {
        super(message);
    }
}
