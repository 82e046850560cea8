package org.kdtree.io;

import java.io.IOException;

/** A malformed input file; the message names the file and the line at fault. */
public class SceneFormatException extends IOException {
    /** The file at fault, as given. */
    private final String file;
    /** The 1-based line at fault, or 0. */
    private final int line;

    /**
     * An error about {@code file} at {@code line}; the message names both.
     *
     * @param file the file at fault, as given
     * @param line the 1-based line at fault, or 0 when the problem is not on one line
     * @param problem what is wrong
     */
    public SceneFormatException(String file, int line, String problem) {
        super(file + (line > 0 ? ":" + line : "") + ": " + problem);
        this.file = file;
        this.line = line;
    }

    /** {@return the file at fault, as given} */
    public String file() { return file; }

    /** {@return the 1-based line at fault, or 0 when the problem is not on one line} */
    public int line() { return line; }
}
