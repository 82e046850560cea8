package org.kdtree.io;

import java.io.BufferedReader;
import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The lines of a text file read as UTF-8, for every reader of the project's formats: a leading
 * byte-order mark is skipped (an editor's, not part of the first line), and a byte that is not
 * UTF-8 (a Latin-1 {@code é} in a comment, say) is reported with its file and line instead of
 * failing somewhere in the decoder with neither.
 *
 * <p>Bytes that are not UTF-8 decode to U+FFFD, which no format of the project uses, and the
 * line that holds one is refused when it is reached: the decoder reads ahead, so only the line
 * itself knows where it is.
 */
final class TextLines implements Closeable {
    private static final char BYTE_ORDER_MARK = '\uFEFF', REPLACEMENT = '\uFFFD';

    private final BufferedReader in;
    private final String name;
    private int line;

    private TextLines(Reader reader, String name) {
        this.in = reader instanceof BufferedReader b ? b : new BufferedReader(reader);
        this.name = name;
    }

    /**
     * Opens {@code file}; a missing file is a one-line error naming it.
     *
     * @param file the file
     * @return its lines
     * @throws IOException if the file is missing or cannot be opened
     */
    public static TextLines open(Path file) throws IOException {
        if (!Files.isRegularFile(file)) throw new SceneFormatException(file.toString(), 0, "no such file");
        InputStream bytes = Files.newInputStream(file);
        return new TextLines(new InputStreamReader(bytes, StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPLACE).onUnmappableCharacter(CodingErrorAction.REPLACE)), file.toString());
    }

    /** What a reader makes of a file's lines (a mesh, points, shapes). */
    interface Parser<T> {
        T parse(TextLines lines) throws IOException;
    }

    /**
     * {@return what {@code parser} makes of the lines of {@code file}}, the file closed after.
     *
     * @param file the file
     * @param parser reads the lines
     * @throws IOException if the file is missing, cannot be read or is malformed
     */
    static <T> T read(Path file, Parser<T> parser) throws IOException {
        try (TextLines lines = open(file)) {
            return parser.parse(lines);
        }
    }

    /**
     * {@return lines of text already decoded}
     *
     * @param reader the text
     * @param name used in error messages
     */
    public static TextLines of(Reader reader, String name) {
        return new TextLines(reader, name);
    }

    /**
     * {@return the whole of {@code file}, checked as {@link #next} checks each line}, lines ended by {@code \n}.
     *
     * @param file the file
     * @throws IOException if the file is missing, unreadable or malformed
     */
    public static String readAll(Path file) throws IOException {
        StringBuilder text = new StringBuilder();
        try (TextLines lines = open(file)) {
            for (String s = lines.next(); s != null; s = lines.next()) text.append(s).append('\n');
        }
        return text.toString();
    }

    /**
     * {@return the next line, or null at the end of the text}
     *
     * @throws IOException if reading fails or the line is not UTF-8
     */
    public String next() throws IOException {
        String s = in.readLine();
        if (s == null) return null;
        line++;
        if (line == 1 && !s.isEmpty() && s.charAt(0) == BYTE_ORDER_MARK) s = s.substring(1);
        int bad = s.indexOf(REPLACEMENT);
        if (bad >= 0)
            throw new SceneFormatException(name, line, "not UTF-8 text (column " + (bad + 1)
                    + " holds a byte such as a Latin-1 accent); save the file as UTF-8");
        return s;
    }

    /** {@return the 1-based number of the line {@link #next} returned last} */
    public int line() { return line; }

    /** {@return the name errors give for this text} */
    public String name() { return name; }

    @Override public void close() throws IOException {
        in.close();
    }
}
