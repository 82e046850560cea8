package org.kdtree.architecture;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/** The main sources as the architecture tests read them: code without comments and string literals. */
final class SourceFiles {
    /** The main sources, relative to the project folder (the tests run there). */
    static final Path MAIN = Path.of("src/main/java");
    private static final Pattern PACKAGE = Pattern.compile("^package\\s+org\\.kdtree\\.([a-z0-9]+)\\s*;", Pattern.MULTILINE);
    private static final Pattern STRIP = Pattern.compile(
            "//[^\\n]*|/\\*.*?\\*/|\"\"\"(?:\\\\.|[^\\\\])*?\"\"\"|\"(?:\\\\.|[^\"\\\\\\n])*\"|'(?:\\\\.|[^'\\\\\\n])+'",
            Pattern.DOTALL);

    private SourceFiles() {
    }

    /** {@return every .java file under src/main/java, sorted} */
    static List<Path> all() {
        try (Stream<Path> files = Files.walk(MAIN)) {
            return files.filter(f -> f.toString().endsWith(".java")).sorted().toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** {@return the file's package below org.kdtree (the one segment), or "" for none} */
    static String packageOf(String source) {
        Matcher m = PACKAGE.matcher(source);
        return m.find() ? m.group(1) : "";
    }

    /** {@return the source with comments, strings and character literals blanked}: what the compiler sees as code. */
    static String code(String source) {
        Matcher m = STRIP.matcher(source);
        StringBuilder out = new StringBuilder();
        while (m.find()) m.appendReplacement(out, m.group().startsWith("/") ? " " : "\"\"");
        m.appendTail(out);
        return out.toString();
    }

    static String read(Path file) {
        try {
            return Files.readString(file);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
