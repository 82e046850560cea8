package org.kdtree.gui;

import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import org.kdtree.shape.Scene2D;
import org.kdtree.tree.KdTree;

/** One canvas repaint into an image, as the workbench does after a rebuild (for the timing test). */
final class RebuildRepaint {
    private RebuildRepaint() {
    }

    static BufferedImage paint(Scene2D shapes, KdTree tree, BufferedImage image) {
        Graphics2D g = image.createGraphics();
        ViewTransform v = new ViewTransform().fit(tree.bounds(), image.getWidth(), image.getHeight());
        TreePainter.paint(g, image.getWidth(), image.getHeight(), shapes, tree, v, TreePainter.Options.PLAIN);
        g.dispose();
        return image;
    }
}
