package org.kdtree.shape;

/** Thrown for geometry that no builder can accept, e.g. a NaN or infinite coordinate. */
public class InvalidGeometryException extends IllegalArgumentException {
    /**
     * An exception with the given message, which should name the offending primitive.
     *
     * @param message the detail message
     */
    public InvalidGeometryException(String message) {
        super(message);
    }
}
