package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.BitSet;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.SharedSettings;
import org.kdtree.geom.Box;
import org.kdtree.io.BundledScenes;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.SahSettings;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.Shape2D;
import org.kdtree.spec.BuilderSpec;

/**
 * The splits a lookahead kept past a local minimum, as the workbench shows them: marked in the
 * model's view of the tree, dashed in their own colour on the canvas with a legend, named so in
 * the tree view; on the long thin object across a field of small ones, where a lookahead of 1
 * keeps one such split (on the talk's figures it keeps one under Kt 30 and Ki 80, none under the
 * default 15 and 20).
 */
class LookaheadDrawingTest {
    private static final int W = 700, H = 700;
    private static final BuilderSpec SAH = BuilderSpec.of("sah");

    private static List<Shape2D> longThin() {
        return BundledScenes.read2D("long-thin.scene2d").shapes();
    }

    @Test void theModelMarksTheSplitsOfItsLookaheadOnly() {
        WorkbenchModel m = new WorkbenchModel();
        m.setScene("long thin", longThin());
        assertThat(marked(m)).as("lookahead 0").isZero();
        m.setSettings(SAH.with(SahSettings.LOOKAHEAD, 1));
        assertThat(marked(m)).as("lookahead 1").isEqualTo(1);
        m.setSettings(SAH.with(SahSettings.LOOKAHEAD, 1).with(SahSettings.LAMBDA, 1.0));
        assertThat(marked(m)).as("lookahead 1, lambda 1").isEqualTo(1);
        m.setSettings(BuilderSpec.of("median-plane"));
        assertThat(marked(m)).as("a median tree, whose splits do not ask the SAH: none marked").isZero();
        m.setScene("talk", BuiltinScenes.talkFigures());
        m.setSettings(SAH.with(SahSettings.LOOKAHEAD, 2));
        assertThat(marked(m)).as("the talk's figures under Kt 15 and Ki 20, where a lookahead changes nothing").isZero();
        m.setSettings(m.settings().with(SharedSettings.KT, 30.0).with(SharedSettings.KI, 80.0));
        assertThat(marked(m)).as("the talk's figures under Kt 30 and Ki 80").isEqualTo(1);
    }

    @Test void aSavedTreeOpenedAgainShowsItsMarks(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir) throws Exception {
        WorkbenchModel m = new WorkbenchModel();
        m.setScene("long thin", longThin());
        m.setSettings(SAH.with(SahSettings.LOOKAHEAD, 1));
        java.nio.file.Path file = dir.resolve("long-thin.kdtree");
        m.saveTree(file);
        m.setSettings(SAH);
        assertThat(marked(m)).isZero();
        m.loadTree(file);
        assertThat(m.loadedFrom()).isEqualTo(file);
        assertThat(marked(m)).as("the saved tree's lookahead split").isEqualTo(1);
    }

    private static int marked(WorkbenchModel m) {
        return ((KdTreeView) m.built()).pastMinimum().cardinality();
    }

    @Test void theMarkedSplitIsDrawnDashedInItsColourWithALegend() {
        Scene2D scene = new Scene2D(longThin());
        KdTreeView view = KdTreeView.of(SAH.with(SahSettings.LOOKAHEAD, 1).create().build(scene), SAH.with(SahSettings.LOOKAHEAD, 1));
        BitSet past = view.pastMinimum();
        assertThat(past.cardinality()).isEqualTo(1);
        int node = past.nextSetBit(0);
        ViewTransform v = new ViewTransform().fit(view.tree().bounds(), W, H);
        BufferedImage img = paint(view, scene, v);
        Box voxel = TreePainter.voxelOf(view.tree(), node);
        int axis = view.tree().axis(node);
        double split = view.tree().split(node);
        int along = 0, coloured = 0;
        for (double t = 0.05; t < 0.95; t += 0.01, along++) {
            double x = axis == 0 ? split : voxel.min(0) + t * voxel.extent(0), y = axis == 1 ? split : voxel.min(1) + t * voxel.extent(1);
            int px = (int) Math.floor(v.screenX(x)), py = (int) Math.floor(v.screenY(y));
            boolean hit = false;
            for (int d = -1; d <= 1; d++) hit |= (axis == 0 ? img.getRGB(px + d, py) : img.getRGB(px, py + d)) == Palette.LOOKAHEAD_SPLIT.getRGB();
            if (hit) coloured++;
        }
        assertThat(coloured).as("points of the marked split in its colour, of %d (dashes and gaps)", along).isBetween(along / 3, along - 5);
        assertThat(count(img, 0, H - 30, 40, H)).as("the legend's sample line").isPositive();
        assertThat(view.nodeText(node)).contains(KdTreeView.PAST_MINIMUM);
        assertThat(view.treeNodes().pathTo(node).getLastPathComponent().toString()).as("the tree view's line").contains(KdTreeView.PAST_MINIMUM);

        KdTreeView none = KdTreeView.of(SAH.create().build(scene), SAH);
        assertThat(count(paint(none, scene, v), 0, 0, W, H)).as("pixels of the colour without a lookahead").isZero();
        for (int n = 0; n < none.tree().nodeCount(); n++) {
            assertThat(none.nodeText(n)).doesNotContain(KdTreeView.PAST_MINIMUM);
            assertThat(none.treeNodes().pathTo(n).getLastPathComponent().toString()).doesNotContain(KdTreeView.PAST_MINIMUM);
        }
    }

    private static BufferedImage paint(KdTreeView view, Scene2D scene, ViewTransform v) {
        BufferedImage img = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        view.paint(g, W, H, scene, v, new TreePainter.Options(-1, -1, false));
        g.dispose();
        return img;
    }

    /** Pixels of {@link Palette#LOOKAHEAD_SPLIT} in [x0, x1) x [y0, y1). */
    private static int count(BufferedImage img, int x0, int y0, int x1, int y1) {
        int n = 0;
        for (int y = y0; y < y1; y++) for (int x = x0; x < x1; x++) if (img.getRGB(x, y) == Palette.LOOKAHEAD_SPLIT.getRGB()) n++;
        return n;
    }
}
