package org.kdtree.treefile;

import java.io.IOException;

/**
 * A tree file refused: one line naming the file and what is wrong with it (truncated, damaged,
 * another format or version, too large, not a tree over these primitives).
 */
public final class TreeFileException extends IOException {
    private static final long serialVersionUID = 1L;

    /**
     * A refusal of {@code file}, in one line: the file, then the reason.
     *
     * @param file   the file as the user named it
     * @param reason what is wrong, in one line
     */
    public TreeFileException(String file, String reason) {
        super(file + ": " + reason);
    }
}
