package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.TreeVisitor;
import org.kdtree.shape.Scene2D;
import org.kdtree.spec.BuilderSpec;

/** Paints the canvas into an image (headless) and reads back what was drawn. */
class TreePainterTest {
    private static final int W = 600, H = 600;

    private record Painted(BufferedImage image, ViewTransform view, KdTree tree) {
        Color at(double x, double y) {
            return new Color(image.getRGB((int) Math.floor(view.screenX(x)), (int) Math.floor(view.screenY(y))));
        }
    }

    private static Painted paint(Scene2D scene, BuilderSpec settings, int selectedNode) {
        KdTree tree = settings.create().build(scene);
        ViewTransform v = new ViewTransform().fit(tree.bounds(), W, H);
        BufferedImage img = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        TreePainter.paint(g, W, H, scene, tree, v, new TreePainter.Options(selectedNode, -1, false));
        g.dispose();
        return new Painted(img, v, tree);
    }

    private static Scene2D talk() {
        return new Scene2D(BuiltinScenes.talkFigures());
    }

    @Test void splitLinesAreDrawnWhereTheTreeHasThem() {
        Painted p = paint(talk(), BuilderSpec.of("median-plane"), -1);
        List<double[]> mids = new ArrayList<>();
        p.tree().walk(new TreeVisitor() {
            @Override public void interior(int node, int depth, Box v, int axis, double split) {
                mids.add(axis == 0 ? new double[] {split, 0.5 * (v.min(1) + v.max(1)), 0}
                        : new double[] {0.5 * (v.min(0) + v.max(0)), split, 1});
            }

            @Override public void leaf(int node, int depth, Box v, int from, int to) { }
        });
        assertThat(mids).hasSizeGreaterThanOrEqualTo(3);
        for (double[] m : mids) {
            // a one-pixel line lands on the pixel row (or column) either side of the exact position
            int px = (int) Math.floor(p.view().screenX(m[0])), py = (int) Math.floor(p.view().screenY(m[1]));
            boolean drawn = false;
            for (int d = -1; d <= 1; d++) {
                int rgb = m[2] == 0 ? p.image().getRGB(px + d, py) : p.image().getRGB(px, py + d);
                drawn |= rgb == Palette.SPLIT_LINE.getRGB();
            }
            assertThat(drawn).as("split line at %s", java.util.Arrays.toString(m)).isTrue();
        }
    }

    @Test void emptyVoxelsAreShadedAndFullOnesAreNot() {
        Painted p = paint(talk(), BuilderSpec.of("sah"), -1);
        int[] counts = new int[2];
        p.tree().walk(new TreeVisitor() {
            @Override public void interior(int node, int depth, Box v, int axis, double split) { }

            @Override public void leaf(int node, int depth, Box v, int from, int to) {
                double cx = 0.5 * (v.min(0) + v.max(0)), cy = 0.5 * (v.min(1) + v.max(1));
                if (from == to) {
                    assertThat(p.at(cx, cy)).as("empty leaf %d", node).isEqualTo(Palette.EMPTY_VOXEL);
                    counts[0]++;
                } else {
                    // a corner pixel just inside a full leaf's voxel: background or object, never the empty shade
                    assertThat(p.at(v.min(0) + 0.3 * v.extent(0), v.min(1) + 0.3 * v.extent(1))).isNotEqualTo(Palette.EMPTY_VOXEL);
                    counts[1]++;
                }
            }
        });
        assertThat(counts[0]).as("the SAH cuts off empty space in the talk's scene").isPositive();
        assertThat(counts[1]).isPositive();
    }

    @Test void aSingleLeafHasNoSplitLineInside() {
        Painted p = paint(talk(), BuilderSpec.of("sah").with(org.kdtree.accel.SharedSettings.MAX_DEPTH, 0), -1);
        assertThat(p.tree().nodeCount()).isEqualTo(1);
        Box b = p.tree().bounds();
        int x0 = (int) p.view().screenX(b.min(0)) + 4, x1 = (int) p.view().screenX(b.max(0)) - 4;
        int y0 = (int) p.view().screenY(b.max(1)) + 4, y1 = (int) p.view().screenY(b.min(1)) - 4;
        for (int y = y0; y < y1; y++)
            for (int x = x0; x < x1; x++) assertThat(p.image().getRGB(x, y)).isNotEqualTo(Palette.SPLIT_LINE.getRGB());
    }

    @Test void linesNearTheRootAreThicker() {
        Painted p = paint(talk(), BuilderSpec.of("median-plane"), -1);
        // the root splits x at the middle; measure its width in pixels on a row through the voxel
        double xi = p.tree().split(0);
        Box b = p.tree().bounds();
        int y = (int) p.view().screenY(b.min(1) + 0.37 * b.extent(1));
        int width = 0;
        for (int x = 0; x < W; x++) {
            if (p.image().getRGB(x, y) == Palette.SPLIT_LINE.getRGB() && Math.abs(x - p.view().screenX(xi)) < 6) width++;
        }
        assertThat(width).isEqualTo((int) TreePainter.lineWidth(0));
        assertThat(TreePainter.lineWidth(0)).isGreaterThan(TreePainter.lineWidth(2)).isGreaterThan(TreePainter.lineWidth(5) - 1);
    }

    @Test void theSelectedLeafAndItsObjectsAreHighlighted() {
        Scene2D scene = talk();
        KdTree tree = BuilderSpec.of("sah").create().build(scene);
        // the leaf holding the small rectangle at (1..2, 1..2)
        int leaf = TreePainter.leafAt(tree, 1.5, 1.5);
        assertThat(tree.isLeaf(leaf)).isTrue();
        Painted p = paint(scene, BuilderSpec.of("sah"), leaf);
        assertThat(p.at(1.5, 1.5)).isEqualTo(Palette.HIGHLIGHT_OBJECT.brighter());
        Box v = TreePainter.voxelOf(tree, leaf);
        // somewhere in that voxel but off the rectangle: the highlight shade
        assertThat(p.at(v.min(0) + 0.05 * v.extent(0), v.max(1) - 0.05 * v.extent(1))).isEqualTo(Palette.HIGHLIGHT_VOXEL);
    }
}
