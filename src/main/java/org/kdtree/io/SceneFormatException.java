package org.kdtree.io;

import java.io.IOException;

/** A malformed input file; the message names the file and the line at fault. */
public class SceneFormatException extends IOException {
    private final String file;
    private final int line;

    public SceneFormatException(String file, int line, String problem) {
        super(file + (line > 0 ? ":" + line : "") + ": " + problem);
        this.file = file;
        this.line = line;
    }

    /** The file at fault, as given. */
    public String file() { return file; }

    /** The 1-based line at fault, or 0 when the problem is not on one line. */
    public int line() { return line; }
}
