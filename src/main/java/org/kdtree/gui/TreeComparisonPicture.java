package org.kdtree.gui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Line2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import org.kdtree.compare.RootFrame;
import org.kdtree.compare.Term;
import org.kdtree.compare.TreeDistance;
import org.kdtree.compare.TreeSignature;
import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.TreeVisitor;
import org.kdtree.shape.Primitives;

/**
 * Two data sets' kd-trees compared in one picture ({@code compare-trees --chart} and the
 * workbench's "Compare data" view): the two trees side by side, each in its root's unit frame (the
 * signature's: centred, scaled by the longest side), the voxels shaded by their leaves' depth,
 * the data and the split lines over them; and a third panel, a heat map of where the leaf depths
 * differ. Above 2-D, the picture is the projection on the first two axes (the mean over the
 * others, and the split lines of those two axes only).
 */
public final class TreeComparisonPicture {
    private static final int SIDE = 420, GAP = 24, TOP = 86, BOTTOM = 64, MAX_DRAWN = 20_000;
    private static final Color SPLIT = new Color(200, 40, 30), DATA = new Color(40, 40, 40);

    /** The picture's width in pixels. */
    public static final int WIDTH = 3 * SIDE + 4 * GAP;
    /** The picture's height in pixels. */
    public static final int HEIGHT = TOP + SIDE + BOTTOM;

    /**
     * One side of the comparison.
     *
     * @param name      what the picture calls it
     * @param data      the data the tree is over
     * @param tree      its kd-tree
     * @param signature the tree's signature
     */
    public record Side(String name, Primitives data, KdTree tree, TreeSignature signature) {
    }

    private TreeComparisonPicture() {
    }

    /**
     * Draws the comparison and writes it as a PNG, whole or not at all.
     *
     * @param file    the PNG file
     * @param a       the first data set
     * @param b       the second, of {@code a}'s dimension
     * @param d       the distance between their signatures
     * @param builder the builder of both trees, as the title names it
     * @throws IOException if the file cannot be written; it is then left as it was
     */
    public static void write(Path file, Side a, Side b, TreeDistance d, String builder) throws IOException {
        BufferedImage image = new BufferedImage(WIDTH, HEIGHT, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        paint(g, a, b, d, builder);
        g.dispose();
        PngExport.write(image, file);
    }

    /**
     * Paints the comparison into {@code g}, {@link #WIDTH} x {@link #HEIGHT} pixels from its origin.
     *
     * @param g       where to paint
     * @param a       the first data set
     * @param b       the second, of {@code a}'s dimension
     * @param d       the distance between their signatures
     * @param builder the builder of both trees, as the title names it
     */
    public static void paint(Graphics2D g, Side a, Side b, TreeDistance d, String builder) {
        int width = WIDTH, height = HEIGHT;
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, width, height);
        double[] occupancyA = a.signature().occupancy(), occupancyB = b.signature().occupancy(), diff = new double[occupancyA.length];
        for (int c = 0; c < diff.length; c++) diff[c] = Math.abs(occupancyA[c] - occupancyB[c]);
        double[] depthA = projected(occupancyA, a.signature(), true), depthB = projected(occupancyB, b.signature(), true);
        diff = projected(diff, a.signature(), false);
        double maxDepth = 0, maxDiff = 0;
        for (int c = 0; c < diff.length; c++) {
            maxDepth = Math.max(maxDepth, Math.max(depthA[c], depthB[c]));
            maxDiff = Math.max(maxDiff, diff[c]);
        }
        header(g, a, b, d, builder);
        int k = a.data().dimension();
        panel(g, GAP, a, depthA, maxDepth, k);
        panel(g, 2 * GAP + SIDE, b, depthB, maxDepth, k);
        heat(g, 3 * GAP + 2 * SIDE, diff, maxDiff);
        legend(g, maxDepth, maxDiff, k);
    }

    private static void header(Graphics2D g, Side a, Side b, TreeDistance d, String builder) {
        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 17));
        g.drawString(String.format(Locale.ROOT, "distance %.4f between the trees of %s and %s", d.total(), a.name(), b.name()), GAP, 24);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 14));
        StringBuilder terms = new StringBuilder();
        for (Term t : Term.values()) terms.append(String.format(Locale.ROOT, "%s %.3f   ", t.label(), d.term(t)));
        g.drawString(terms + "(each in [0, 1], weight 1/4; builder " + builder + ")", GAP, 46);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 14));
        g.drawString(title(a), GAP, TOP - 10);
        g.drawString(title(b), 2 * GAP + SIDE, TOP - 10);
        g.drawString("where the leaf depth differs", 3 * GAP + 2 * SIDE, TOP - 10);
    }

    private static String title(Side s) {
        return String.format(Locale.ROOT, "%s: %d leaves, depth up to %d", s.name(), s.signature().leaves(), s.signature().maxDepth());
    }

    /** One tree: voxels shaded by depth, the data, the split lines, the root's outline. */
    private static void panel(Graphics2D g, int x0, Side s, double[] depth, double maxDepth, int k) {
        int side = (int) Math.round(Math.sqrt(depth.length));
        cells(g, x0, depth, side, maxDepth, new Color(225, 236, 250), new Color(30, 80, 160));
        RootFrame frame = new RootFrame(s.tree().bounds());
        g.setClip(x0, TOP, SIDE, SIDE);
        data(g, x0, s.data(), frame, k);
        splits(g, x0, s.tree(), frame, k);
        g.setClip(null);
        Box root = s.tree().bounds();
        g.setColor(Color.BLACK);
        g.setStroke(new BasicStroke(1.5f));
        g.draw(rect(x0, frame, root, k));
        g.setColor(Color.GRAY);
        g.setStroke(new BasicStroke(1f));
        g.drawRect(x0, TOP, SIDE, SIDE);
    }

    private static void cells(Graphics2D g, int x0, double[] value, int side, double max, Color low, Color high) {
        double cell = (double) SIDE / side;
        for (int y = 0; y < side; y++)
            for (int x = 0; x < side; x++) {
                double v = value[y * side + x];
                if (v <= 0) continue;
                g.setColor(mix(low, high, max > 0 ? v / max : 0));
                g.fill(new Rectangle2D.Double(x0 + x * cell, TOP + SIDE - (y + 1) * cell, cell + 0.5, cell + 0.5));
            }
    }

    private static void data(Graphics2D g, int x0, Primitives data, RootFrame frame, int k) {
        Box box = new Box(data.dimension());
        int stride = Math.max(1, data.size() / MAX_DRAWN);
        g.setColor(DATA);
        g.setStroke(new BasicStroke(0.8f));
        for (int i = 0; i < data.size(); i += stride) {
            data.bounds(i, box);
            Rectangle2D r = rect(x0, frame, box, k);
            if (r.getWidth() < 2 && r.getHeight() < 2) g.fill(new Rectangle2D.Double(r.getCenterX() - 1, r.getCenterY() - 1, 2.2, 2.2));
            else g.draw(r);
        }
    }

    private static void splits(Graphics2D g, int x0, KdTree tree, RootFrame frame, int k) {
        g.setColor(SPLIT);
        tree.walk(new TreeVisitor() {
            @Override public void interior(int node, int depth, Box voxel, int axis, double split) {
                if (axis > 1) return;
                g.setStroke(new BasicStroke((float) Math.max(0.6, 3 - 0.35 * depth)));
                double u = frame.toUnit(axis, split);
                double lo = k > 1 ? frame.toUnit(1 - axis, voxel.min(1 - axis)) : 0, hi = k > 1 ? frame.toUnit(1 - axis, voxel.max(1 - axis)) : 1;
                if (axis == 0) g.draw(new Line2D.Double(px(x0, u), py(lo), px(x0, u), py(hi)));
                else g.draw(new Line2D.Double(px(x0, lo), py(u), px(x0, hi), py(u)));
            }

            @Override public void leaf(int node, int depth, Box voxel, int from, int to) {
            }
        });
    }

    /** The difference panel: white where the trees' leaves are equally deep, dark red where they differ most. */
    private static void heat(Graphics2D g, int x0, double[] diff, double maxDiff) {
        int side = (int) Math.round(Math.sqrt(diff.length));
        cells(g, x0, diff, side, maxDiff, new Color(255, 236, 200), new Color(150, 0, 0));
        g.setColor(Color.GRAY);
        g.setStroke(new BasicStroke(1f));
        g.drawRect(x0, TOP, SIDE, SIDE);
    }

    private static void legend(Graphics2D g, double maxDepth, double maxDiff, int k) {
        int y = TOP + SIDE + 22;
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 13));
        ramp(g, GAP, y, new Color(225, 236, 250), new Color(30, 80, 160), "leaf depth 0", String.format(Locale.ROOT, "%.1f", maxDepth));
        g.setColor(Color.BLACK);
        g.drawString("red: split planes (thicker nearer the root); dark: the data", 2 * GAP + SIDE, y + 12);
        ramp(g, 3 * GAP + 2 * SIDE, y, new Color(255, 236, 200), new Color(150, 0, 0), "|depth A - depth B|: 0",
                String.format(Locale.ROOT, "%.1f levels", maxDiff));
        g.setColor(Color.DARK_GRAY);
        g.drawString("both roots centred and scaled by their longest side: a shifted or scaled copy looks the same"
                + (k > 2 ? ". Projected on axes 0 and 1: the trees' deepest leaf, the differences' mean over the other axes" : ""), GAP, y + 36);
    }

    private static void ramp(Graphics2D g, int x, int y, Color low, Color high, String from, String to) {
        g.setColor(Color.BLACK);
        int w = g.getFontMetrics().stringWidth(from);
        g.drawString(from, x, y + 12);
        for (int i = 0; i < 120; i++) {
            g.setColor(mix(low, high, i / 119.0));
            g.fillRect(x + w + 6 + i, y, 1, 16);
        }
        g.setColor(Color.BLACK);
        g.drawString(to, x + w + 132, y + 12);
    }

    /**
     * A grid picture on axes 0 and 1, at most 64 cells a side: over the other grid axes (and, in
     * 1-D, over runs of cells) the largest value ({@code deepest}) or the mean.
     */
    private static double[] projected(double[] values, TreeSignature s, boolean deepest) {
        int side = s.cellsPerAxis(), bits = Integer.numberOfTrailingZeros(side), out = Math.min(side, 64);
        boolean twoAxes = s.gridAxes() > 1;
        double[] sum = new double[out * out];
        int[] count = new int[out * out];
        for (int c = 0; c < values.length; c++) {
            int x = (c & (side - 1)) * out / side, y = twoAxes ? ((c >>> bits) & (side - 1)) * out / side : 0;
            sum[y * out + x] = deepest ? Math.max(sum[y * out + x], values[c]) : sum[y * out + x] + values[c];
            count[y * out + x]++;
        }
        if (!deepest) for (int c = 0; c < sum.length; c++) sum[c] = count[c] > 0 ? sum[c] / count[c] : 0;
        if (!twoAxes) for (int y = 1; y < out; y++) System.arraycopy(sum, 0, sum, y * out, out);   // 1-D: the strip fills the square
        return sum;
    }

    private static Rectangle2D rect(int x0, RootFrame frame, Box box, int k) {
        double x1 = frame.toUnit(0, box.min(0)), x2 = frame.toUnit(0, box.max(0));
        double y1 = k > 1 ? frame.toUnit(1, box.min(1)) : 0, y2 = k > 1 ? frame.toUnit(1, box.max(1)) : 1;
        return new Rectangle2D.Double(px(x0, x1), py(y2), (x2 - x1) * SIDE, (y2 - y1) * SIDE);
    }

    private static double px(int x0, double u) { return x0 + u * SIDE; }

    private static double py(double v) { return TOP + (1 - v) * SIDE; }

    private static Color mix(Color a, Color b, double t) {
        double u = Math.max(0, Math.min(1, t));
        return new Color((int) Math.round(a.getRed() + u * (b.getRed() - a.getRed())),
                (int) Math.round(a.getGreen() + u * (b.getGreen() - a.getGreen())),
                (int) Math.round(a.getBlue() + u * (b.getBlue() - a.getBlue())));
    }
}
