package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.HashSet;
import java.util.Set;
import javax.swing.tree.TreePath;
import org.junit.jupiter.api.Test;
import org.kdtree.bvh.Bvh;
import org.kdtree.generate.Shapes;
import org.kdtree.shape.Scene2D;

/** Paints a bounding volume hierarchy into an image (headless) and reads back what was drawn. */
class BvhPainterTest {
    private static final int W = 600, H = 600;

    private record Painted(BufferedImage image, ViewTransform view, Bvh bvh, int boxes) {
    }

    private static Bvh bvh(Scene2D scene) {
        return new org.kdtree.bvh.BvhBuilder().build(scene);
    }

    private static Painted paint(Scene2D scene, Bvh bvh, int selected) {
        ViewTransform v = new ViewTransform().fit(bvh.bounds(), W, H);
        BufferedImage img = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        int boxes = BvhPainter.paint(g, W, H, scene, bvh, v, new TreePainter.Options(selected, -1, false));
        g.dispose();
        return new Painted(img, v, bvh, boxes);
    }

    private static Set<Integer> colours(BufferedImage img) {
        Set<Integer> out = new HashSet<>();
        for (int y = 0; y < img.getHeight(); y++) for (int x = 0; x < img.getWidth(); x++) out.add(img.getRGB(x, y));
        return out;
    }

    @Test void everyNodesBoxIsDrawnInItsDepthsColour() {
        Scene2D scene = new Scene2D(Shapes.clustered(200, 4).shapes());
        Bvh h = bvh(scene);
        assertThat(h.maxDepth()).as("200 objects in leaves of at most 16").isGreaterThanOrEqualTo(3);
        Painted p = paint(scene, h, -1);
        assertThat(p.boxes()).isEqualTo(h.nodeCount());
        int[] depth = BvhPainter.depths(h);
        Set<Integer> seen = colours(p.image());
        for (int n = 0; n < h.nodeCount(); n++)
            if (!h.isLeaf(n)) assertThat(seen).as("an interior box at depth %d", depth[n]).contains(Palette.bvhDepth(depth[n]).getRGB());
        assertThat(seen).as("the leaves' outline").contains(Palette.BVH_LEAF_LINE.getRGB());
        assertThat(Palette.bvhDepth(0).getRGB()).isNotEqualTo(Palette.bvhDepth(1).getRGB());
    }

    /** Two fans of 20 thin segments that cross: their leaves' boxes overlap where the lines leave gaps. */
    private static Scene2D crossingFans() {
        java.util.List<org.kdtree.shape.Shape2D> s = new java.util.ArrayList<>();
        for (int i = 0; i < 20; i++) {
            s.add(new org.kdtree.shape.Shape2D.Segment(0, 0.25 * i, 10, 5 + 0.25 * i));
            s.add(new org.kdtree.shape.Shape2D.Segment(0, 10 - 0.25 * i, 10, 5 - 0.25 * i));
        }
        return new Scene2D(s);
    }

    @Test void leavesAreTintedAndOverlapsDarker() {
        Scene2D scene = crossingFans();
        Bvh h = bvh(scene);
        Painted p = paint(scene, h, -1);
        Color once = over(Palette.BVH_LEAF, Palette.BACKGROUND), twice = over(Palette.BVH_LEAF, once);
        Set<Integer> seen = colours(p.image());
        assertThat(seen).as("a leaf's tint on the background").contains(once.getRGB());
        assertThat(overlappingLeaves(h)).as("the fans' leaf boxes overlap").isTrue();
        assertThat(seen).as("two leaves' tints where their boxes overlap").contains(twice.getRGB());
    }

    private static boolean overlappingLeaves(Bvh h) {
        for (int a = 0; a < h.nodeCount(); a++)
            for (int b = a + 1; b < h.nodeCount(); b++)
                if (h.isLeaf(a) && h.isLeaf(b) && overlap(h, a, b, 0) > 0 && overlap(h, a, b, 1) > 0) return true;
        return false;
    }

    private static double overlap(Bvh h, int a, int b, int axis) {
        return Math.min(h.max(a, axis), h.max(b, axis)) - Math.max(h.min(a, axis), h.min(b, axis));
    }

    /** The colour {@code top} (translucent) leaves over {@code under}, as Java 2D blends it into an RGB image. */
    private static Color over(Color top, Color under) {
        BufferedImage one = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = one.createGraphics();
        g.setColor(under);
        g.fillRect(0, 0, 1, 1);
        g.setColor(top);
        g.fillRect(0, 0, 1, 1);
        g.dispose();
        return new Color(one.getRGB(0, 0));
    }

    @Test void theLeafUnderAPointIsTheSmallestThatHoldsIt() {
        Scene2D scene = new Scene2D(Shapes.uniform(150, 2).shapes());
        Bvh h = bvh(scene);
        java.util.Random r = new java.util.Random(5);
        for (int i = 0; i < 300; i++) {
            double x = h.min(0, 0) + r.nextDouble() * (h.max(0, 0) - h.min(0, 0));
            double y = h.min(0, 1) + r.nextDouble() * (h.max(0, 1) - h.min(0, 1));
            int leaf = BvhPainter.leafAt(h, x, y);
            double best = Double.POSITIVE_INFINITY;
            int expected = -1;
            for (int n = 0; n < h.nodeCount(); n++) {
                double area = (h.max(n, 0) - h.min(n, 0)) * (h.max(n, 1) - h.min(n, 1));
                boolean holds = x >= h.min(n, 0) && x <= h.max(n, 0) && y >= h.min(n, 1) && y <= h.max(n, 1);
                if (h.isLeaf(n) && holds && area < best) { best = area; expected = n; }
            }
            assertThat(leaf).as("(%f, %f)", x, y).isEqualTo(expected);
        }
        assertThat(BvhPainter.leafAt(h, h.max(0, 0) + 1, 0)).isEqualTo(-1);
    }

    @Test void theSelectedNodesBoxAndObjectsAreHighlighted() {
        Scene2D scene = new Scene2D(BuiltinScenes.talkFigures());
        Bvh h = bvh(scene);
        int leaf = BvhPainter.leafAt(h, 1.5, 1.5);   // the small rectangle at (1..2, 1..2)
        assertThat(leaf).isNotNegative();
        Painted p = paint(scene, h, leaf);
        ViewTransform v = p.view();
        assertThat(new Color(p.image().getRGB((int) v.screenX(1.5), (int) v.screenY(1.5))))
                .isEqualTo(Palette.HIGHLIGHT_OBJECT.brighter());
    }

    @Test void theTreeViewsPathsFollowTheHierarchy() {
        Bvh h = bvh(new Scene2D(Shapes.uniform(100, 1).shapes()));
        BvhTreeModel tm = new BvhTreeModel(h);
        for (int n = 0; n < h.nodeCount(); n++) {
            TreePath p = tm.pathTo(n);
            assertThat(tm.node(p.getLastPathComponent())).isEqualTo(n);
            assertThat(tm.node(p.getPathComponent(0))).isZero();
            for (int i = 1; i < p.getPathCount(); i++)
                assertThat(tm.getIndexOfChild(p.getPathComponent(i - 1), p.getPathComponent(i))).isNotNegative();
        }
        assertThat(tm.getRoot().toString()).startsWith("#0  box [");
    }
}
