package org.kdtree.scene;

import org.kdtree.limits.Limits;

/**
 * A pinhole camera: eye, look-at point, up vector, vertical field of view and image size.
 * Pixel (x, y) has its top-left corner at (x, y); a sample at (x + sx, y + sy) with
 * sx, sy in [0, 1).
 */
public final class Camera {
    private final Vec3 eye;
    private final Vec3 forward, right, up;
    private final double tanHalfFov;
    private final int width, height;

    /**
     * A camera at {@code eye} looking at {@code lookAt}.
     *
     * @param eye the eye point
     * @param lookAt the point the camera looks at, in the image centre
     * @param upHint a direction that is up in the image (need not be orthogonal to the view direction)
     * @param fovDegrees vertical field of view, in (0, 180)
     * @param width image width in pixels
     * @param height image height in pixels
     */
    public Camera(Vec3 eye, Vec3 lookAt, Vec3 upHint, double fovDegrees, int width, int height) {
        this.eye = eye;
        this.forward = lookAt.minus(eye).normalized();
        this.right = forward.cross(upHint).normalized();
        this.up = right.cross(forward);
        this.tanHalfFov = Math.tan(Math.toRadians(fovDegrees) / 2);
        this.width = Limits.IMAGE_SIDE.check("width", width);
        this.height = Limits.IMAGE_SIDE.check("height", height);
    }

    /** {@return the eye point} */
    public Vec3 eye() { return eye; }
    /** {@return the image width in pixels} */
    public int width() { return width; }
    /** {@return the image height in pixels} */
    public int height() { return height; }

    /**
     * {@return the same camera at another image size} (the aspect ratio follows the size).
     *
     * @param w the new width in pixels
     * @param h the new height in pixels
     */
    public Camera withSize(int w, int h) {
        return new Camera(eye, eye.plus(forward), up, Math.toDegrees(2 * Math.atan(tanHalfFov)), w, h);
    }

    /**
     * Writes the unit direction of the ray through image point (px, py), in pixels from the top-left, to {@code out}.
     *
     * @param px x in pixels
     * @param py y in pixels
     * @param out receives x, y, z
     */
    public void direction(double px, double py, double[] out) {
        double aspect = (double) width / height;
        double sx = (2 * px / width - 1) * tanHalfFov * aspect;
        double sy = (1 - 2 * py / height) * tanHalfFov;
        out[0] = forward.x() + right.x() * sx + up.x() * sy;
        out[1] = forward.y() + right.y() * sx + up.y() * sy;
        out[2] = forward.z() + right.z() * sx + up.z() * sy;
        Vectors.normalize(out);
    }
}
