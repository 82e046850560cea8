package org.kdtree.gui;

import java.awt.Graphics2D;

/** Something drawn over the scene and tree, such as the ray and the traversal's current step. */
interface CanvasOverlay {
    /**
     * Paints over the scene and tree, in screen coordinates.
     *
     * @param g the canvas's graphics
     * @param view maps scene coordinates to pixels
     */
    void paint(Graphics2D g, ViewTransform view);
}
