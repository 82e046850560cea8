package org.kdtree.gui;

import org.kdtree.geom.Box;

/**
 * Maps scene coordinates (y up) to screen pixels (y down): a uniform scale and an offset.
 * Zoom keeps the point under the mouse fixed; pan moves by pixels.
 */
final class ViewTransform {
    private double scale = 1, offsetX, offsetY;

    /**
     * Fits {@code box}, with a margin, into a {@code width x height} pixel area.
     *
     * @param box the scene box to show
     * @param width the area's width in pixels
     * @param height the area's height in pixels
     * @return this transform
     */
    public ViewTransform fit(Box box, int width, int height) {
        double w = box.isEmpty() ? 0 : box.max(0) - box.min(0), h = box.isEmpty() ? 0 : box.max(1) - box.min(1);
        // a point-sized scene (or none) gets a 10 x 10 window; a flat one the extent of its long side
        double longest = Math.max(w, h);
        double least = longest > 0 ? longest * 1e-3 : 10;
        w = Math.max(w, least);
        h = Math.max(h, least);
        int margin = 24;
        scale = Math.min((width - 2.0 * margin) / w, (height - 2.0 * margin) / h);
        if (!(scale > 0) || !Double.isFinite(scale)) scale = 1;
        double cx = box.isEmpty() ? 0 : 0.5 * (box.min(0) + box.max(0));
        double cy = box.isEmpty() ? 0 : 0.5 * (box.min(1) + box.max(1));
        offsetX = width / 2.0 - cx * scale;
        offsetY = height / 2.0 + cy * scale;
        return this;
    }

    /** {@return pixels per scene unit} */
    public double scale() { return scale; }

    /**
     * {@return the pixel column of scene x}
     *
     * @param x a scene x
     */
    public double screenX(double x) { return offsetX + x * scale; }
    /**
     * {@return the pixel row of scene y} (y grows upward in the scene, downward on screen).
     *
     * @param y a scene y
     */
    public double screenY(double y) { return offsetY - y * scale; }
    /**
     * {@return the scene x of pixel column {@code px}}
     *
     * @param px a pixel column
     */
    public double worldX(double px) { return (px - offsetX) / scale; }
    /**
     * {@return the scene y of pixel row {@code py}}
     *
     * @param py a pixel row
     */
    public double worldY(double py) { return (offsetY - py) / scale; }

    /**
     * Zooms by {@code factor} around the pixel (px, py).
     *
     * @param px the pixel column that stays put
     * @param py the pixel row that stays put
     * @param factor above 1 to zoom in, below 1 to zoom out
     */
    public void zoomAt(double px, double py, double factor) {
        double wx = worldX(px), wy = worldY(py);
        scale *= factor;
        offsetX = px - wx * scale;
        offsetY = py + wy * scale;
    }

    /**
     * Moves the view by (dx, dy) pixels.
     *
     * @param dx pixels to the right
     * @param dy pixels down
     */
    public void pan(double dx, double dy) {
        offsetX += dx;
        offsetY += dy;
    }

    /**
     * {@return whether {@code o} maps every point as this one does}
     *
     * @param o another transform, or null
     */
    public boolean sameAs(ViewTransform o) {
        return o != null && o.scale == scale && o.offsetX == offsetX && o.offsetY == offsetY;
    }

    /** {@return a copy of this transform} */
    public ViewTransform copy() {
        ViewTransform t = new ViewTransform();
        t.scale = scale; t.offsetX = offsetX; t.offsetY = offsetY;
        return t;
    }
}
