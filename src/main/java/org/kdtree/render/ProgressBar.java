package org.kdtree.render;

import java.io.PrintStream;

/** A one-line console progress bar, redrawn in place; safe to update from several threads. */
public final class ProgressBar {
    private static final int WIDTH = 40;
    private final PrintStream out;
    private final int total;
    private int shown = -1;

    /** @param out where to draw (stderr, so stdout stays clean for the summary); null for none */
    public ProgressBar(PrintStream out, int total) {
        this.out = out;
        this.total = Math.max(1, total);
    }

    /** Reports that {@code done} of the total units are finished. */
    public synchronized void update(int done) {
        if (out == null) return;
        int percent = (int) (100L * done / total);
        if (percent <= shown) return; // threads may report out of order: never move backwards
        shown = percent;
        int filled = WIDTH * done / total;
        out.print("\r[" + "#".repeat(filled) + "-".repeat(WIDTH - filled) + "] " + percent + "% (" + done + "/" + total
                + " tiles)");
        if (done >= total) out.println();
        out.flush();
    }
}
