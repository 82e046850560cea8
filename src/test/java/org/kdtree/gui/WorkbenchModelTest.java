package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import javax.swing.tree.TreePath;
import org.junit.jupiter.api.Test;
import org.kdtree.generate.Shapes;
import org.kdtree.shape.Shape2D;
import org.kdtree.spec.BuilderSpec;

class WorkbenchModelTest {
    @Test void everyChangeRebuildsTheTree() throws Exception {
        WorkbenchModel m = new WorkbenchModel();
        awaitBuild(m); // a cold machine may deliver the empty scene's tree after the wait, to a listener added by then
        List<WorkbenchModel.Change> heard = new ArrayList<>();
        m.addListener(heard::add);
        m.setScene("t", Shapes.clustered(300, 3).shapes());
        int sahNodes = m.tree().nodeCount();
        m.setSettings(m.settings().with(org.kdtree.kdtree.SahSettings.LAMBDA, 1.0));
        assertThat(m.tree()).isNotNull();
        m.setSettings(m.settings().forBuilder("median-plane").with(org.kdtree.kdtree.CyclingAxisBuilder.MIN_PRIMITIVES, 1));
        assertThat(m.tree().builderName()).isEqualTo("median-plane");
        m.addShape(new Shape2D.Point(5, 5));
        assertThat(m.scene().size()).isEqualTo(301);
        assertThat(m.selectedShape()).isEqualTo(300);
        m.removeShape(300);
        assertThat(m.scene().size()).isEqualTo(300);
        assertThat(heard).containsOnly(WorkbenchModel.Change.TREE).hasSize(5);
        assertThat(sahNodes).isGreaterThan(1);

        m.setSettings(BuilderSpec.of("sah").with(org.kdtree.kdtree.SahSettings.ALGORITHM, org.kdtree.kdtree.SahBuilder.Algorithm.SORTED));
        assertThat(m.tree().nodeCount()).as("every exact plane search builds the same tree").isEqualTo(sahNodes);
    }

    @Test void scenesSaveAndLoadBack(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir) throws Exception {
        WorkbenchModel m = new WorkbenchModel();
        m.setScene("mixed", Shapes.mixed(40, 2).shapes());
        java.nio.file.Path f = dir.resolve("mixed.scene2d");
        m.save(f);
        WorkbenchModel n = new WorkbenchModel();
        n.load(f);
        assertThat(n.scene().shapes()).isEqualTo(m.scene().shapes());
        assertThat(n.sceneName()).isEqualTo("mixed.scene2d");
        java.nio.file.Files.writeString(dir.resolve("bad.scene2d"), "rect 1 2 3\n");
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> n.load(dir.resolve("bad.scene2d")))
                .hasMessageContaining("bad.scene2d").hasMessageContaining("1");
    }

    /** Issue 43: File > Save tree and Open tree: the same tree and statistics, its settings the workbench's; another scene's refused. */
    @Test void treesSaveAndOpenOverTheSceneShown(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir) throws Exception {
        WorkbenchModel m = new WorkbenchModel();
        m.setScene("mixed", Shapes.mixed(300, 2).shapes());
        BuilderSpec spec = BuilderSpec.of("sah").with(org.kdtree.kdtree.SahSettings.LAMBDA, 0.6);
        m.setSettings(spec);
        java.nio.file.Path f = dir.resolve("mixed.kdtree");
        m.saveTree(f);
        org.kdtree.accel.TreeStats built = m.built().stats();
        WorkbenchModel n = new WorkbenchModel();
        n.setScene("mixed", Shapes.mixed(300, 2).shapes());
        List<WorkbenchModel.Change> heard = new ArrayList<>();
        n.addListener(heard::add);
        n.loadTree(f);
        assertThat(heard).containsExactly(WorkbenchModel.Change.TREE);
        assertThat(n.built().stats()).isEqualTo(built);
        assertThat(n.settings()).isEqualTo(spec);
        assertThat(n.loadedFrom()).isEqualTo(f);
        assertThat(new StatsPanel(n).value("build time")).endsWith("(a load of mixed.kdtree)");
        n.setScene("other", Shapes.mixed(300, 3).shapes());
        assertThat(n.loadedFrom()).as("an edit builds anew").isNull();
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> n.loadTree(f)).isInstanceOf(org.kdtree.treefile.TreeFileException.class)
                .hasMessageContaining("the tree was built over other 300 2-D shapes");
        m.setSettings(BuilderSpec.of("bvh"));
        awaitBuild(m);
        m.saveTree(f);
        n.setScene("mixed", Shapes.mixed(300, 2).shapes());
        n.loadTree(f);
        assertThat(n.settings().builder()).isEqualTo("bvh");
        assertThat(n.built().stats()).isEqualTo(m.built().stats());
    }

    @Test void theCanvasExportsAsPng(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir) throws Exception {
        WorkbenchModel m = new WorkbenchModel();
        m.setScene("talk", BuiltinScenes.talkFigures());
        TreeCanvas c = new TreeCanvas(m);
        c.setSize(400, 300);
        java.nio.file.Path f = dir.resolve("canvas.png");
        PngExport.write(c.snapshot(), f);
        java.awt.image.BufferedImage back = javax.imageio.ImageIO.read(f.toFile());
        assertThat(back.getWidth()).isEqualTo(400);
        assertThat(back.getHeight()).isEqualTo(300);
        boolean shaded = false;
        for (int y = 0; y < 300; y++) for (int x = 0; x < 400; x++) shaded |= back.getRGB(x, y) == Palette.EMPTY_VOXEL.getRGB();
        assertThat(shaded).isTrue();

        // hovering the small rectangle's leaf highlights it over the cached picture
        m.selectNode(TreePainter.leafAt(m.tree(), 1.5, 1.5));
        java.awt.image.BufferedImage hover = c.snapshot();
        ViewTransform v = c.view();
        assertThat(hover.getRGB((int) v.screenX(1.5), (int) v.screenY(1.5))).isEqualTo(Palette.HIGHLIGHT_OBJECT.brighter().getRGB());
        m.selectNode(-1);
        assertThat(c.snapshot().getRGB((int) v.screenX(1.5), (int) v.screenY(1.5))).isEqualTo(Palette.OBJECT_FILL.getRGB());
    }

    @Test void anEmptySceneAndASinglePointStillBuildDrawAndTrace() {
        WorkbenchModel m = new WorkbenchModel();
        m.setScene("empty", List.of());
        TreeCanvas c = new TreeCanvas(m);
        c.setSize(300, 200);
        c.fit();
        assertThat(c.view().scale()).isBetween(1.0, 100.0);
        assertThat(c.snapshot().getWidth()).isEqualTo(300);
        assertThat(TraversalRecorder.record(m.tree(), m.scene(), new double[] {-1, 0, 1, 0}).hitObject()).isEqualTo(-1);
        m.addShape(new Shape2D.Point(2, 3));
        c.fit();
        assertThat(c.view().scale()).isBetween(1.0, 100.0);
        assertThat(TraversalRecorder.record(m.tree(), m.scene(), new double[] {0, 3, 1, 0}).hitObject()).isZero();
        m.addShape(new Shape2D.Rect(1, 1, 4, 1)); // zero height: never hit, still drawn and built
        assertThat(c.snapshot().getHeight()).isEqualTo(200);
    }

    @Test void editingMovesShapesAndCorners() {
        Shape2D r = new Shape2D.Rect(0, 0, 2, 1);
        assertThat(ShapeEditing.translate(r, 1, 1)).isEqualTo(new Shape2D.Rect(1, 1, 3, 2));
        int corner = ShapeEditing.vertexNear(r, 2, 1, 0.1);
        assertThat(ShapeEditing.moveHandle(r, corner, 4, 3)).isEqualTo(new Shape2D.Rect(0, 0, 4, 3));
        List<Shape2D> shapes = List.of(r, new Shape2D.Segment(5, 5, 6, 6));
        assertThat(ShapeEditing.pick(shapes, 5.5, 5.5, 0.01)).isEqualTo(1);
        assertThat(ShapeEditing.pick(shapes, 1, 0.5, 0.01)).isZero();
        assertThat(ShapeEditing.pick(shapes, 8, 8, 0.01)).isEqualTo(-1);
        assertThat(ShapeEditing.created(EditTool.TRIANGLE, 0, 0, 2, 0)).isInstanceOf(Shape2D.Triangle.class);
    }

    @Test void treeViewPathsFollowTheTree() {
        WorkbenchModel m = new WorkbenchModel();
        m.setScene("t", Shapes.uniform(100, 1).shapes());
        var tree = m.tree();
        KdTreeModel tm = new KdTreeModel(tree, new java.util.BitSet());
        for (int n = 0; n < tree.nodeCount(); n++) {
            TreePath p = tm.pathTo(n);
            assertThat(((KdTreeModel.NodeRef) p.getLastPathComponent()).node()).isEqualTo(n);
            for (int i = 1; i < p.getPathCount(); i++)
                assertThat(tm.getIndexOfChild(p.getPathComponent(i - 1), p.getPathComponent(i))).isNotNegative();
        }
    }

    @Test void theHierarchyIsBuiltDrawnAndTracedInPlaceOfTheTree() throws Exception {
        WorkbenchModel m = new WorkbenchModel();
        m.setScene("talk", BuiltinScenes.talkFigures());
        m.setSettings(m.settings().forBuilder("bvh").with(org.kdtree.accel.SharedSettings.LEAF_SIZE, 1));
        awaitBuild(m);
        assertThat(m.built()).isInstanceOf(BvhView.class);
        assertThat(m.tree()).as("no kd-tree while the hierarchy is shown").isNull();
        assertThat(m.built().builderName()).isEqualTo("bvh");
        assertThat(m.built().stats().leaves()).as("one object per leaf").isEqualTo(m.scene().size());
        TreeCanvas c = new TreeCanvas(m);
        c.setSize(400, 300);
        java.awt.image.BufferedImage img = c.snapshot();
        boolean leafLine = false;
        for (int y = 0; y < 300; y++) for (int x = 0; x < 400; x++) leafLine |= img.getRGB(x, y) == Palette.BVH_LEAF_LINE.getRGB();
        assertThat(leafLine).as("the leaves' boxes are drawn").isTrue();
        TraversalTrace t = TraversalRecorder.record(m.built().structure(), m.scene(), new double[] {0, 1.5, 1, 0});
        assertThat(t.hitObject()).as("the small rectangle at (1..2, 1..2)").isNotNegative();
        assertThat(t.boxTests()).isPositive();

        m.setSettings(m.settings().forBuilder("sah"));
        assertThat(m.built()).isInstanceOf(KdTreeView.class);
        assertThat(m.tree().builderName()).isEqualTo("sah");
    }

    /**
     * Waits for a build the model left running in the background, as the window does: a small
     * scene's build normally ends within the model's wait, but a JVM's first hierarchy also loads
     * its tracing kernels (the Vector API's on JDK 25), which on a loaded machine can take longer.
     */
    private static void awaitBuild(WorkbenchModel m) throws Exception {
        boolean[] building = {true};
        for (long end = System.nanoTime() + 60_000_000_000L; System.nanoTime() < end; Thread.sleep(20)) {
            javax.swing.SwingUtilities.invokeAndWait(() -> building[0] = m.building());
            if (!building[0]) return;
        }
        throw new AssertionError("the build did not end within 60 s");
    }
}
