package org.kdtree.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.kdtree.accel.Setting;
import org.kdtree.files.AtomicFile;
import org.kdtree.kdtree.BuilderFault;

/**
 * What the command line prints when a command fails: one line, never a stack trace. A user's
 * mistake (bad file, bad option) says what is wrong (a setting refused by the library, named
 * there by its name, is named here by the option the user typed); a builder's own fault (a plug-in's that
 * threw, answered wrongly, hung or was slow) names the builder, the method and the node;
 * running out of memory says how much the JVM had and how to give it more; anything else is a
 * bug of ours, reported as one line with the path of a file that holds the full trace.
 */
final class Failure {
    /** Exit codes: a user's mistake, out of memory, a builder's fault, an unexpected failure. */
    static final int USAGE = 2, MEMORY = 3, BUILDER = 4, INTERNAL = 70;

    private Failure() {
    }

    /** Prints the line for {@code failure} to {@code err} and returns the exit code. */
    static int report(Throwable failure, java.io.PrintWriter err) {
        if (failure instanceof Setting.Refused refused) {   // the library names the setting; the user typed its option
            err.println("error: " + refused.message(Setting::option));
            return USAGE;
        }
        if (failure instanceof IOException || failure instanceof IllegalArgumentException) {
            err.println("error: " + failure.getMessage());
            return USAGE;
        }
        if (failure instanceof java.awt.AWTError || failure instanceof java.awt.HeadlessException) {
            err.println("error: cannot open a window (" + failure.getMessage() + "); the commands render, stats, raycast and "
                    + "tradeoff need no display");
            return USAGE;
        }
        if (failure instanceof BuilderFault fault) {
            err.println("error: " + fault.getMessage());
            return BUILDER;
        }
        if (failure instanceof OutOfMemoryError) {
            long mb = Runtime.getRuntime().maxMemory() >> 20;
            err.println("error: out of memory (Java may use " + mb + " MB here); give it more, for example "
                    + "java -Xmx" + Math.max(2, 4 * mb >> 10) + "g -jar kdtree.jar ..., or use a smaller scene or setting");
            return MEMORY;
        }
        err.println("error: unexpected " + failure.getClass().getSimpleName()
                + (failure.getMessage() != null ? ": " + failure.getMessage() : "") + saved(failure));
        return INTERNAL;
    }

    /** Writes the full trace to a temporary file; returns where, as the end of the error line. */
    private static String saved(Throwable failure) {
        try {
            Path file = Files.createTempFile("kdtree-error-", ".txt");
            StringWriter trace = new StringWriter();
            failure.printStackTrace(new PrintWriter(trace));
            AtomicFile.writeString(file, trace.toString());
            return " (a bug of ours: the full report is in " + file + ")";
        } catch (IOException | RuntimeException e) {
            return " (a bug of ours; the report could not be written: " + e.getMessage() + ")";
        }
    }
}
