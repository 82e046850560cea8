package org.kdtree.gui;

import java.nio.file.Files;
import java.nio.file.Path;
import javax.swing.SwingUtilities;

/**
 * Takes the screenshots of docs/workbench.md from the real window: opens the workbench, sets
 * up each view, and grabs the screen with ImageMagick's {@code import} (or, where that is not
 * installed, with AWT's {@code Robot}). Run under Xvfb:
 * <pre>
 * Xvfb :99 -screen 0 1300x900x24 &amp;
 * mvn -B -q -Ptools test-compile dependency:build-classpath -Dmdep.outputFile=target/cp.txt -Dmdep.includeScope=test
 * DISPLAY=:99 java -cp target/classes:target/test-classes:$(cat target/cp.txt) org.kdtree.gui.Screenshots docs/images
 * </pre>
 */
public final class Screenshots {
    private Screenshots() {
    }

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args.length > 0 ? args[0] : "docs/images");
        Files.createDirectories(out);
        if (args.length > 2 && args[1].equals("--screen")) {
            screen(out, args[2], args.length > 3 && args[3].equals("bvh"));
            return;
        }
        if (args.length > 1 && args[1].equals("lookahead")) {
            lookahead(out);
            return;
        }
        Workbench b = window();
        WorkbenchModel m = b.model();
        on(() -> m.selectNode(TreePainter.leafAt(m.tree(), 3.2, 6.5)));
        shot(out, "build-2d.png");

        on(() -> {
            b.scenes().selectBuiltin(3);
            m.selectShape(m.scene().size() - 1);
            m.selectNode(TreePainter.leafAt(m.tree(), 5.0, 5.3));
        });
        shot(out, "long-thin.png");

        on(() -> {
            b.scenes().selectBuiltin(2);
            m.selectNode(-1);
        });
        shot(out, "clustered-sah.png");

        on(() -> m.setSettings(m.settings().forBuilder("median-plane")));
        shot(out, "clustered-median.png");

        on(() -> {
            m.setSettings(m.settings().forBuilder("sah"));
            StepperPanel s = b.stepper();
            int target = 0;
            // a ray that hits something, shown at an object test with far children on the stack
            for (double y = 1.0; y < 9 && target == 0; y += 0.25) {
                m.setRay(0.2, y, 9.8, 9.5 - y);
                if (s.trace().hitObject() < 0) continue;
                for (int i = 0; i < s.trace().size(); i++) {
                    TraversalTrace.Step st = s.trace().step(i);
                    if (st.kind() == TraversalTrace.Kind.TEST && st.stack().size() >= 2) { target = i; break; }
                }
            }
            s.controls().first();
            for (int i = 0; i < target; i++) s.controls().forward();
        });
        shot(out, "stepper.png");

        double[][] ray = new double[1][];
        on(() -> {
            ray[0] = m.ray();
            m.clearRay();
            NearestStepperPanel s = b.nearest();
            s.setK(4);
            m.setQuery(5.3, 3.6);
            // the second node pruned once the list is full: the radius, a pruned voxel and its bound
            int target = s.trace().size() - 1, seen = 0;
            for (int i = 0; i < s.trace().size(); i++) {
                NearestTrace.Step st = s.trace().step(i);
                if (st.kind() == NearestTrace.Kind.PRUNE && Double.isFinite(st.kth()) && ++seen == 2) { target = i; break; }
            }
            s.controls().first();
            for (int i = 0; i < target; i++) s.controls().forward();
        });
        shot(out, "knn.png");

        on(() -> {
            m.clearQuery();
            b.scenes().selectBuiltin(1);
            b.tabs().setSelectedIndex(3);
            b.collisions().reset();
            for (int i = 0; i < 90; i++) b.collisions().stepOnce();
        });
        shot(out, "collisions.png");

        on(() -> {
            b.scenes().selectBuiltin(2);
            m.setRay(ray[0][0], ray[0][1], ray[0][0] + ray[0][2], ray[0][1] + ray[0][3]);
            b.tabs().setSelectedIndex(1);
        });
        shot(out, "compare.png");

        on(() -> b.compare().choose(0, "bvh"));
        shot(out, "compare-bvh.png");

        on(() -> {
            b.compare().choose(0, CompareView.DEFAULT_BUILDERS.get(0));
            b.tabs().setSelectedIndex(0);
            m.setSettings(m.settings().forBuilder("bvh"));
            // the hierarchy's stepper at a box test, with boxes saved on the stack
            StepperPanel s = b.stepper();
            int target = 0;
            for (int i = 0; i < s.trace().size() && target == 0; i++) {
                TraversalTrace.Step st = s.trace().step(i);
                if (st.kind() == TraversalTrace.Kind.BOX_TEST && st.boxes().size() == 2 && st.stack().size() >= 2) target = i;
            }
            s.controls().first();
            for (int i = 0; i < target; i++) s.controls().forward();
        });
        shot(out, "bvh-2d.png");
        on(() -> m.setSettings(m.settings().forBuilder("sah")));

        View3D v = (View3D) b.tabs().getComponentAt(2);
        on(() -> {
            v.choose("cornell-box.json", 400);
            b.tabs().setSelectedIndex(2);   // opening the tab starts the render
        });
        awaitTiles(v, 0.4);                 // the image part done, the tiles spread over it as they are taken
        shot(out, "view3d-progress.png", 100);
        boolean[] busy = {true};
        for (int i = 0; i < 1200 && busy[0]; i++) {
            Thread.sleep(100);
            on(() -> busy[0] = v.busy());
        }
        shot(out, "view3d.png");
        on(b::dispose);
        System.exit(0);
    }

    /**
     * The whole screen (Xvfb's, e.g. 1024 x 768) with the workbench as the command line opens it
     * (fitted to the screen), a ray cast and stepped to its middle: {@code workbench-NAME.png}.
     */
    private static void screen(Path out, String name, boolean bvh) throws Exception {
        Workbench[] w = new Workbench[1];
        SwingUtilities.invokeAndWait(() -> {
            w[0] = new Workbench();
            w[0].setVisible(true);
        });
        WorkbenchModel m = w[0].model();
        on(() -> {
            if (bvh) m.setSettings(m.settings().forBuilder("bvh"));
            m.setRay(0.2, 2.0, 9.8, 7.0);
            StepperPanel s = w[0].stepper();
            s.controls().first();
            if (bvh) s.controls().last();   // the end: nothing current, nothing lit as if tested
            else for (int i = 0; i < s.trace().size() / 2; i++) s.controls().forward();
        });
        Thread.sleep(1500);
        java.awt.Rectangle all = new java.awt.Rectangle(java.awt.Toolkit.getDefaultToolkit().getScreenSize());
        java.awt.image.BufferedImage img = new java.awt.Robot().createScreenCapture(all);
        javax.imageio.ImageIO.write(img, "png", out.resolve("workbench-" + name + (bvh ? "-bvh" : "") + ".png").toFile());
        on(w[0]::dispose);
        System.exit(0);
    }

    /**
     * The split a lookahead kept past a local minimum, dashed, under the SAH with a lookahead of 1,
     * nothing selected (a selection's outline would cover the dashes): the long thin object across
     * a field of small ones ({@code lookahead-long-thin.png}), and the talk's figures with Kt 30
     * and Ki 80, under which it keeps one (under 15 and 20 it keeps none) ({@code lookahead-talk.png}).
     */
    private static void lookahead(Path out) throws Exception {
        Workbench b = window();
        WorkbenchModel m = b.model();
        on(() -> {
            b.scenes().selectBuiltin(3);
            m.setSettings(m.settings().forBuilder("sah").with(org.kdtree.kdtree.SahSettings.LOOKAHEAD, 1));
            m.selectNode(-1);
        });
        shot(out, "lookahead-long-thin.png");
        on(() -> {
            b.scenes().selectBuiltin(0);
            m.setSettings(m.settings().with(org.kdtree.accel.SharedSettings.KT, 30.0).with(org.kdtree.accel.SharedSettings.KI, 80.0));
        });
        shot(out, "lookahead-talk.png");
        on(b::dispose);
        System.exit(0);
    }

    /** {@return the workbench's window at 1280 x 880 in the screen's upper left corner, shown} */
    private static Workbench window() throws Exception {
        Workbench[] w = new Workbench[1];
        SwingUtilities.invokeAndWait(() -> {
            w[0] = new Workbench();
            w[0].setSize(1280, 880);
            w[0].setLocation(0, 0);
            w[0].setVisible(true);
        });
        return w[0];
    }

    private static void on(Runnable r) throws Exception {
        SwingUtilities.invokeAndWait(r);
    }

    private static void shot(Path dir, String name) throws Exception {
        shot(dir, name, 1200);
    }

    /** Grabs the screen after {@code settleMillis} (a render in progress: briefly, or it has ended). */
    private static void shot(Path dir, String name, long settleMillis) throws Exception {
        Thread.sleep(settleMillis);
        Process p;
        try {
            p = new ProcessBuilder("import", "-window", "root", "-crop", "1280x880+0+0", dir.resolve(name).toString())
                    .inheritIO().start();
        } catch (java.io.IOException noImageMagick) {   // without ImageMagick, AWT's robot grabs the same pixels
            java.awt.image.BufferedImage img = new java.awt.Robot().createScreenCapture(new java.awt.Rectangle(0, 0, 1280, 880));
            javax.imageio.ImageIO.write(img, "png", dir.resolve(name).toFile());
            return;
        }
        if (p.waitFor() != 0) throw new IllegalStateException("import failed for " + name);
    }

    /** Waits until the 3-D view's status says at least {@code share} of the tiles are rendered (or 30 s pass). */
    private static void awaitTiles(View3D v, double share) throws Exception {
        java.util.regex.Pattern p = java.util.regex.Pattern.compile("rendering: (\\d+) / (\\d+) tiles");
        String[] text = {""};
        for (int i = 0; i < 3000; i++) {
            on(() -> { String t = statusOf(v); text[0] = t == null ? "" : t; });
            java.util.regex.Matcher m = p.matcher(text[0]);
            if (m.find() && Integer.parseInt(m.group(1)) >= share * Integer.parseInt(m.group(2))) return;
            Thread.sleep(10);
        }
    }

    private static String statusOf(java.awt.Container c) {
        for (java.awt.Component k : c.getComponents()) {
            if (k instanceof javax.swing.JLabel l && "view3d.status".equals(l.getName())) return l.getText();
            if (k instanceof java.awt.Container sub) {
                String t = statusOf(sub);
                if (t != null) return t;
            }
        }
        return null;
    }
}
