package org.kdtree.tradeoff;

import de.erichseifert.vectorgraphics2d.Processors;
import de.erichseifert.vectorgraphics2d.VectorGraphics2D;
import de.erichseifert.vectorgraphics2d.util.PageSize;
import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.time.LocalDate;
import java.util.List;
import java.util.Locale;
import javax.imageio.ImageIO;
import org.kdtree.files.AtomicFile;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.markers.Marker;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * What makes every chart the project writes readable on its own: log axes labelled at each
 * decade and at 2 and 5 between, one marker and colour per series, a caption that says what was
 * measured where and when, and one file, PNG or SVG, as its name says.
 */
public final class ChartFile {
    private static final Marker[] MARKERS = {SeriesMarkers.CIRCLE, SeriesMarkers.DIAMOND, SeriesMarkers.SQUARE,
            SeriesMarkers.TRIANGLE_UP, SeriesMarkers.TRIANGLE_DOWN, SeriesMarkers.CROSS, SeriesMarkers.PLUS};
    /** Tableau's 20 colours (each hue dark, then light) and twelve more: one colour a series for every study's variants. */
    private static final Color[] COLOURS = {new Color(0x1f77b4), new Color(0xff7f0e), new Color(0x2ca02c),
            new Color(0xd62728), new Color(0x9467bd), new Color(0x8c564b), new Color(0xe377c2), new Color(0x7f7f7f),
            new Color(0xbcbd22), new Color(0x17becf), new Color(0xaec7e8), new Color(0xffbb78), new Color(0x98df8a),
            new Color(0xff9896), new Color(0xc5b0d5), new Color(0xc49c94), new Color(0xf7b6d2), new Color(0x4d4d4d),
            new Color(0xdbdb8d), new Color(0x9edae5), new Color(0x000080), new Color(0x808000), new Color(0x800000),
            new Color(0x008080), new Color(0x393b79), new Color(0x637939), new Color(0x8c6d31), new Color(0x843c39),
            new Color(0x7b4173), new Color(0x5254a3), new Color(0xe7ba52), new Color(0xad494a)};
    /** The caption's font, and the height of one of its lines. */
    private static final Font CAPTION_FONT = new Font(Font.SANS_SERIF, Font.PLAIN, 12);
    private static final int CAPTION_LINE = 16;
    /** How the axes write numbers, the same for XChart's decades and the ticks drawn here. */
    private static final String NUMBER_PATTERN = "#,##0.####";

    /** The dashed line of a reference series (break-even, the exact search, brute force). */
    static final BasicStroke DASHED = new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10,
            new float[] {6, 4}, 0);

    private ChartFile() {
    }

    /**
     * A new chart of the size every chart of the docs has (900 x 600, the caption added below it by {@link #write}).
     *
     * @param title  the chart's title
     * @param xTitle the x axis's title
     * @param yTitle the y axis's title
     * @return the chart, without series
     */
    public static XYChart newChart(String title, String xTitle, String yTitle) {
        return new XYChartBuilder().width(900).height(600).title(title).xAxisTitle(xTitle).yAxisTitle(yTitle).build();
    }

    /**
     * Log scale on both axes. XChart labels the decades (its custom tick formatters assume linear
     * axes, and its own log labels at every 1..9 overlap), so {@link #write} adds the ticks and
     * labels at 2 and 5 of every decade itself, from {@link #intermediateTicks}.
     *
     * @param chart the chart to set up
     */
    public static void logAxes(XYChart chart) {
        chart.getStyler().setXAxisLogarithmic(true).setYAxisLogarithmic(true);
        chart.getStyler().setXAxisLogarithmicDecadeOnly(true).setYAxisLogarithmicDecadeOnly(true);
        chart.getStyler().setXAxisDecimalPattern(NUMBER_PATTERN).setYAxisDecimalPattern(NUMBER_PATTERN);
        chart.getStyler().setAxisTickLabelsColor(HIDDEN);   // every label drawn by intermediateLabels, in one way
    }

    /**
     * The ticks a log axis gets labelled besides XChart's decades: 2 and 5 times a power of ten
     * within {@code [lo, hi]}; where that makes fewer than three labels with the decades (data
     * spanning less than a decade), every 2..9 times a power of ten; and where even that does,
     * evenly spaced round values (1, 2 or 5 times a power of ten apart).
     *
     * @param lo the low end of the axis's range, > 0
     * @param hi the high end, >= {@code lo}
     * @return the values in ascending order, never a power of ten; empty if the range is not positive or is empty
     */
    public static List<Double> intermediateTicks(double lo, double hi) {
        if (!(lo > 0) || !(hi >= lo)) return new java.util.ArrayList<>();
        int decades = decadesWithin(lo, hi);
        List<Double> out = mantissaTicks(lo, hi, new int[] {2, 5});
        if (decades + out.size() < 3) out = mantissaTicks(lo, hi, new int[] {2, 3, 4, 5, 6, 7, 8, 9});
        if (decades + out.size() < 3) out = evenTicks(lo, hi);
        return out;
    }

    /** The values m times a power of ten within {@code [lo, hi]}, for each m of {@code mantissas}. */
    private static List<Double> mantissaTicks(double lo, double hi, int[] mantissas) {
        List<Double> out = new java.util.ArrayList<>();
        for (double decade = Math.pow(10, Math.floor(Math.log10(lo))); decade <= hi; decade *= 10)
            for (int m : mantissas) {
                double v = Double.parseDouble(m + "e" + Math.round(Math.log10(decade)));   // exact decimal, no drift
                if (v >= lo && v <= hi) out.add(v);
            }
        return out;
    }

    /** Round values from {@code lo} to {@code hi}, about four steps apart, powers of ten left to XChart. */
    private static List<Double> evenTicks(double lo, double hi) {
        java.math.BigDecimal step = niceStep((hi - lo) / 4);
        List<Double> out = new java.util.ArrayList<>();
        if (step.signum() <= 0) return out;
        java.math.BigDecimal v = java.math.BigDecimal.valueOf(lo).divide(step, 0, java.math.RoundingMode.CEILING).multiply(step);
        for (; v.doubleValue() <= hi; v = v.add(step))
            if (!v.stripTrailingZeros().unscaledValue().equals(java.math.BigInteger.ONE)) out.add(v.doubleValue());
        return out;
    }

    /** 1, 2 or 5 times a power of ten, the largest not above {@code raw} (zero for a zero span). */
    private static java.math.BigDecimal niceStep(double raw) {
        if (!(raw > 0)) return java.math.BigDecimal.ZERO;
        int exp = (int) Math.floor(Math.log10(raw));
        double m = raw / Math.pow(10, exp);
        return new java.math.BigDecimal((m >= 5 ? 5 : m >= 2 ? 2 : 1) + "E" + exp);
    }

    /** How many powers of ten lie within {@code [lo, hi]}: the ticks XChart labels itself. */
    private static int decadesWithin(double lo, double hi) {
        int n = 0;
        for (long e = (long) Math.floor(Math.log10(lo)) - 1; e <= (long) Math.ceil(Math.log10(hi)) + 1; e++) {
            double decade = Double.parseDouble("1e" + e);   // exact decimal, as the ticks
            if (decade >= lo && decade <= hi) n++;
        }
        return n;
    }

    /**
     * A new chart with a logarithmic y axis, large markers and the legend outside on the right:
     * the nearest-neighbour studies' charts.
     *
     * @param title  the chart's title
     * @param xTitle the x axis's title
     * @param yTitle the y axis's title
     * @return the chart, without series
     */
    public static XYChart newLogYChart(String title, String xTitle, String yTitle) {
        XYChart chart = newChart(title, xTitle, yTitle);
        chart.getStyler().setMarkerSize(9).setLegendPosition(org.knowm.xchart.style.Styler.LegendPosition.OutsideE);
        logYAxis(chart);
        return chart;
    }

    /**
     * Log scale on the y axis only, for charts whose x is a fraction or a small count (recall,
     * dimension), which a log scale would only distort; labelled as {@link #logAxes} labels.
     *
     * @param chart the chart to set up
     */
    public static void logYAxis(XYChart chart) {
        chart.getStyler().setYAxisLogarithmic(true).setYAxisLogarithmicDecadeOnly(true);
        chart.getStyler().setYAxisDecimalPattern(NUMBER_PATTERN);
    }

    /**
     * How a tick value is written, as XChart writes the decades: "20", "0.05", "2,000,000".
     *
     * @param v the tick's value
     * @return its label
     */
    public static String tickLabel(double v) {
        return new java.text.DecimalFormat(NUMBER_PATTERN, java.text.DecimalFormatSymbols.getInstance(Locale.ROOT)).format(v);
    }

    /**
     * Gives the i-th series colour i mod 32 and marker i mod 7: up to 32 series (the whole trade-off
     * study's variants) each have a colour of their own, and the markers tell apart any pair whose
     * colours are near (32 and 7 are coprime: no two of up to 224 series share both).
     *
     * @param series the chart's series, in the order they were added
     */
    public static void distinctMarkers(List<XYSeries> series) {
        for (int i = 0; i < series.size(); i++) {
            series.get(i).setMarker(MARKERS[i % MARKERS.length]);
            series.get(i).setMarkerColor(COLOURS[i % COLOURS.length]);
            series.get(i).setLineColor(COLOURS[i % COLOURS.length]);
        }
    }

    /**
     * "what was measured · N threads on a machine of C cores · date", for under a chart.
     *
     * @param what    what was measured
     * @param threads the threads the measurement used
     * @return the caption, with this machine's core count and today's date
     */
    public static String caption(String what, int threads) {
        return what + " · " + threads + (threads == 1 ? " thread" : " threads") + " on a machine of "
                + Runtime.getRuntime().availableProcessors() + " cores · " + LocalDate.now();
    }

    /**
     * Refuses a chart file whose name says neither format, before any work.
     *
     * @param option the option that named it, for the message
     * @param file   the chart file
     * @throws IllegalArgumentException unless its name ends in {@code .png} or {@code .svg}
     */
    public static void requireFormat(String option, Path file) {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (!name.endsWith(".png") && !name.endsWith(".svg"))
            throw new IllegalArgumentException(option + " " + file + ": a chart is written as .png or .svg");
    }

    /**
     * Writes the chart with its caption to {@code file}: as SVG if its name ends in {@code .svg},
     * else as PNG. One file per chart: the docs keep each chart in one format.
     *
     * @param chart   the chart to draw
     * @param caption the text under the chart, wrapped to its width
     * @param file    the PNG or SVG file to write
     * @throws IOException if the file cannot be written
     */
    public static void write(XYChart chart, String caption, Path file) throws IOException {
        List<String> lines = captionLines(caption, chart.getWidth() - 20);
        int w = chart.getWidth(), h = chart.getHeight() + CAPTION_LINE * lines.size() + 10;
        if (file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".svg")) {
            VectorGraphics2D vg = new VectorGraphics2D();
            paint(chart, lines, vg);
            AtomicFile.write(file, out -> Processors.get("svg").getDocument(vg.getCommands(), new PageSize(0, 0, w, h)).writeTo(out));
            return;
        }
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        paint(chart, lines, g);
        g.dispose();
        AtomicFile.write(file, out -> {
            if (!ImageIO.write(image, "png", out)) throw new IOException(file + ": no PNG writer");
        });
    }

    /**
     * Draws the 2 and 5 ticks of each log axis, with their labels, where XChart drew its decades:
     * the data's range fills the plot's central {@code plotContentSize} share, which places the axes.
     */
    private static void intermediateLabels(XYChart chart, Graphics2D g) {
        double[] x = range(chart, true), y = range(chart, false);
        if (x == null || y == null) return;
        double pad = (1 - chart.getStyler().getPlotContentSize()) / 2 / chart.getStyler().getPlotContentSize();
        double x0 = chart.getScreenXFromChart(x[0]), x1 = chart.getScreenXFromChart(x[1]);
        double y0 = chart.getScreenYFromChart(y[0]), y1 = chart.getScreenYFromChart(y[1]);
        double axisY = y0 + (y0 - y1) * pad, axisX = x0 - (x1 - x0) * pad;
        g.setFont(chart.getStyler().getAxisTickLabelsFont());
        boolean all = HIDDEN.equals(chart.getStyler().getAxisTickLabelsColor());   // XChart draws none: draw the decades too
        g.setColor(all ? LABELS : chart.getStyler().getAxisTickLabelsColor());
        var fm = g.getFontMetrics();
        // Every label of a log axis, the decades too, drawn here in one font on one baseline, over
        // the whole axis (the data's range and the plot's padding on either side), not just the data's.
        for (double v : !chart.getStyler().isXAxisLogarithmic() ? List.<Double>of() : all ? axisTicks(padded(x, pad), x) : intermediateTicks(x[0], x[1])) {
            int sx = (int) Math.round(chart.getScreenXFromChart(v));
            g.drawLine(sx, (int) axisY, sx, (int) axisY + 3);
            String t = tickLabel(v);
            g.drawString(t, sx - fm.stringWidth(t) / 2, (int) axisY + 5 + fm.getAscent());
        }
        for (double v : !chart.getStyler().isYAxisLogarithmic() ? List.<Double>of() : all ? axisTicks(padded(y, pad), y) : intermediateTicks(y[0], y[1])) {
            int sy = (int) Math.round(chart.getScreenYFromChart(v));
            g.drawLine((int) axisX - 3, sy, (int) axisX, sy);
            String t = tickLabel(v);
            g.drawString(t, (int) axisX - 5 - fm.stringWidth(t), sy + fm.getAscent() / 2 - 1);
        }
    }

    /** The colour of the axes' labels, which this class draws on a log axis (XChart's own are made transparent there). */
    private static final Color LABELS = Color.BLACK;
    private static final Color HIDDEN = new Color(0, 0, 0, 0);

    /** A log axis's ends: the data's range widened by the plot's padding on either side, in log space, as XChart lays it out. */
    private static double[] padded(double[] range, double pad) {
        if (!(range[0] > 0) || range[1] <= range[0]) return range;
        double lo = Math.log10(range[0]), hi = Math.log10(range[1]), span = hi - lo;
        return new double[] {Math.pow(10, lo - pad * span), Math.pow(10, hi + pad * span)};
    }

    /**
     * Every labelled tick of a log axis over {@code axis}: its decades and {@link #intermediateTicks},
     * ascending; and, where the data reach beyond the outermost of those, one more round value
     * (1 to 9 times a power of ten) past the data's extreme, or failing that the roundest before
     * the axis's end, so that no point stands beyond every label.
     *
     * @param axis the axis's ends, > 0
     * @param data the data's smallest and largest value on it
     * @return the ticks, ascending
     */
    static List<Double> axisTicks(double[] axis, double[] data) {
        List<Double> ticks = new java.util.ArrayList<>(intermediateTicks(axis[0], axis[1]));
        if (!(axis[0] > 0)) return ticks;
        for (int e = (int) Math.floor(Math.log10(axis[0])); ; e++) {   // from a decade at or below the axis: log10 may round
            double decade = Double.parseDouble("1e" + e);
            if (decade > axis[1]) break;
            if (decade >= axis[0]) ticks.add(decade);
        }
        ticks.sort(null);
        if (ticks.isEmpty() || ticks.get(ticks.size() - 1) < data[1]) {
            Double up = roundAtLeast(data[1]);
            if (up <= axis[1]) ticks.add(up);
            else if (roundAtMost(axis[1]) > (ticks.isEmpty() ? 0 : ticks.get(ticks.size() - 1))) ticks.add(roundAtMost(axis[1]));
        }
        if (ticks.get(0) > data[0]) {
            Double down = roundAtMost(data[0]);
            if (down >= axis[0]) ticks.add(0, down);
            else if (roundAtLeast(axis[0]) < ticks.get(0)) ticks.add(0, roundAtLeast(axis[0]));
        }
        return ticks;
    }

    /** The least m times a power of ten (m in 1..9) at or above {@code v} > 0. */
    private static double roundAtLeast(double v) {
        int e = (int) Math.floor(Math.log10(v));
        for (int m = 1; m <= 10; m++) {
            double r = Double.parseDouble(m + "e" + e);
            if (r >= v) return r;
        }
        return Double.parseDouble("1e" + (e + 1));
    }

    /** The greatest m times a power of ten (m in 1..9) at or below {@code v} > 0. */
    private static double roundAtMost(double v) {
        int e = (int) Math.floor(Math.log10(v));
        for (int m = 9; m >= 1; m--) {
            double r = Double.parseDouble(m + "e" + e);
            if (r <= v) return r;
        }
        return Double.parseDouble("9e" + (e - 1));
    }

    /** The smallest and largest x (or y) over all series, or null when there is no data. */
    private static double[] range(XYChart chart, boolean xAxis) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (XYSeries s : chart.getSeriesMap().values())
            for (double v : xAxis ? s.getXData() : s.getYData()) {
                lo = Math.min(lo, v);
                hi = Math.max(hi, v);
            }
        return lo <= hi ? new double[] {lo, hi} : null;
    }

    /** The caption broken at its " · " separators into lines that fit {@code width} pixels. */
    private static List<String> captionLines(String caption, int width) {
        Graphics2D g = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB).createGraphics();
        var fm = g.getFontMetrics(CAPTION_FONT);
        g.dispose();
        List<String> lines = new java.util.ArrayList<>();
        String line = "";
        for (String part : caption.split(" · ")) {
            String longer = line.isEmpty() ? part : line + " · " + part;
            if (!line.isEmpty() && fm.stringWidth(longer) > width) {
                lines.add(line);
                line = part;
            } else {
                line = longer;
            }
        }
        lines.add(line);
        return lines;
    }

    private static void paint(XYChart chart, List<String> caption, Graphics2D g) {
        int w = chart.getWidth(), h = chart.getHeight();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, w, h + CAPTION_LINE * caption.size() + 10);
        chart.paint(g, w, h);
        intermediateLabels(chart, g);
        g.setColor(new Color(60, 60, 60));
        g.setFont(CAPTION_FONT);
        for (int i = 0; i < caption.size(); i++) g.drawString(caption.get(i), 10, h + CAPTION_LINE * (i + 1));
    }
}
