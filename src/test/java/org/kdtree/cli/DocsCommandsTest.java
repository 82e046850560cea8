package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.SimpleJavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine;

/**
 * Issue 34, item 7: the docs as a reader types them. Every command line of the README and docs/
 * that runs the application ({@code java -jar ... kdtree.jar ...}, in a code block or a code
 * span) names only options its command has; one with no placeholders ({@code MESH}, {@code [...]},
 * {@code a|b}) parses as written, and the project's files it names exist. Every Java code block
 * compiles against the library as a user's code would (outside its packages): a whole class as
 * it stands, a method as a builder's, statements in a method whose class declares what the
 * surrounding text gives (a {@code mesh}, a {@code tree}, ...; {@code ...} is what the reader has).
 * The README's example is also built and run from an empty folder by {@code .ci/readme-check}.
 */
class DocsCommandsTest {
    private static final Pattern FENCE = Pattern.compile("(?ms)^\\s*```(\\w*)\\n(.*?)^\\s*```");
    private static final Pattern SPAN = Pattern.compile("`([^`\\n]+)`");
    private static final Pattern JAR = Pattern.compile("java (?:-\\S+ )*-jar \\S*kdtree\\.jar\\b(.*)|org\\.kdtree\\.cli\\.Main\\b(.*)");

    /** The Markdown files a reader follows: the README and every file under docs/. */
    private static List<Path> docs() throws IOException {
        List<Path> all = new ArrayList<>(List.of(Path.of("README.md")));
        try (Stream<Path> files = Files.walk(Path.of("docs"))) {
            files.filter(f -> f.toString().endsWith(".md")).sorted().forEach(all::add);
        }
        return all;
    }

    /** A command as the docs write it, with where. */
    record Command(String where, String text) {
    }

    /** Every application command: lines of fenced and indented blocks, and code spans, continuation lines joined. */
    static List<Command> commands() throws IOException {
        List<Command> found = new ArrayList<>();
        for (Path doc : docs()) {
            String[] lines = Files.readString(doc).split("\n", -1);
            boolean fenced = false;
            for (int i = 0; i < lines.length; i++) {
                String line = lines[i];
                if (line.strip().startsWith("```")) {
                    fenced = !fenced;
                    continue;
                }
                boolean code = fenced || line.startsWith("    ") && !line.strip().startsWith("-") && !line.strip().startsWith("|");
                List<String> texts = new ArrayList<>();
                if (code) {
                    StringBuilder joined = new StringBuilder(line);
                    while (joined.toString().stripTrailing().endsWith("\\") && i + 1 < lines.length) {
                        joined.setLength(joined.toString().stripTrailing().length() - 1);
                        joined.append(' ').append(lines[++i].strip());
                    }
                    texts.add(joined.toString());
                } else {
                    Matcher m = SPAN.matcher(line);
                    while (m.find()) texts.add(m.group(1));
                }
                for (String t : texts) if (JAR.matcher(t).find()) found.add(new Command(doc + ":" + (i + 1), t.strip()));
            }
        }
        return found;
    }

    /** The arguments after the jar (or Main), up to a comment, a pipe, a redirection or the next shell command. */
    static List<String> arguments(String command) {
        Matcher m = JAR.matcher(command);
        if (!m.find()) throw new IllegalArgumentException(command);
        String rest = m.group(1) != null ? m.group(1) : m.group(2);
        List<String> args = new ArrayList<>();
        StringBuilder token = new StringBuilder();
        char quote = 0;
        for (int i = 0; i <= rest.length(); i++) {
            char c = i < rest.length() ? rest.charAt(i) : ' ';
            if (quote != 0) {
                if (c == quote) quote = 0; else token.append(c);
                continue;
            }
            if (c == '\'' || c == '"') { quote = c; continue; }
            boolean end = c == '#' && token.length() == 0 || c == ';' || c == '>' && !token.toString().endsWith("-")
                    || c == '&' && i + 1 < rest.length() && rest.charAt(i + 1) == '&' || c == ')'
                    || c == '|' && token.length() == 0;
            if (Character.isWhitespace(c) || end) {
                if (token.length() > 0) args.add(token.toString());
                token.setLength(0);
                if (end) break;
            } else {
                token.append(c);
            }
        }
        return args;
    }

    /** Whether the command is a synopsis (placeholders, optional parts, alternatives) rather than one to type as it is. */
    static boolean synopsis(List<String> args) {
        for (String a : args)
            if (a.contains("[") || a.contains("]") || a.contains("|") || a.contains("...") || a.contains("..") && !a.startsWith("..")
                    || a.contains("<") || a.equals("OPTIONS") || a.matches(".*\\b[A-Z][A-Z_]{2,}\\b.*") && !a.startsWith("$"))
                return true;
        return false;
    }

    @Test void everyCommandInTheDocsNamesOnlyOptionsItsCommandHas() throws IOException {
        List<Command> commands = commands();
        assertThat(commands).as("commands found in the docs").hasSizeGreaterThan(40);
        List<String> wrong = new ArrayList<>();
        for (Command c : commands) {
            List<String> args = new ArrayList<>(arguments(c.text()));
            for (int i = 0; i < args.size(); i++)                 // --plugin is read before picocli, as Main does
                if (args.get(i).equals("--plugin") && i + 1 < args.size()) { args.remove(i + 1); args.remove(i--); }
                else if (args.get(i).startsWith("--plugin=")) args.remove(i--);
            CommandLine cl = new CommandLine(new Main()).setCaseInsensitiveEnumValuesAllowed(true);
            CommandSpec spec = cl.getCommandSpec();
            args.replaceAll(a -> a.matches("\\$\\w+") ? "1" : a);  // a shell loop's variable ("--threads $t")
            String name = args.isEmpty() || args.get(0).startsWith("-") || args.get(0).startsWith("[") ? null : args.get(0);
            if (name != null && name.matches("[A-Z]+")) name = null;  // "COMMAND ...": any of them
            if (name != null) {
                if (!cl.getSubcommands().containsKey(name)) { wrong.add(c.where() + ": no command '" + name + "': " + c.text()); continue; }
                spec = cl.getSubcommands().get(name).getCommandSpec();
            }
            for (String a : args) {
                if (a.equals("--")) break;
                String option = a.replaceFirst("^\\[+", "").replaceFirst("[=\\]].*", "");
                if (!option.matches("--?[A-Za-z][\\w-]*")) continue;
                if (spec.findOption(option) == null && cl.getCommandSpec().findOption(option) == null)
                    wrong.add(c.where() + ": " + (name == null ? "kdtree" : name) + " has no option " + option + ": " + c.text());
            }
            if (synopsis(args)) continue;
            for (String a : args) {
                if (a.startsWith("../")) wrong.add(c.where() + ": " + a + " is outside the project (the docs' meshes are $MESHES/...): " + c.text());
                if (a.startsWith("scenes/") && !Files.exists(Path.of(a))) wrong.add(c.where() + ": no file " + a + ": " + c.text());
            }
            try {
                new CommandLine(new Main()).setCaseInsensitiveEnumValuesAllowed(true).parseArgs(args.toArray(String[]::new));
            } catch (CommandLine.ParameterException e) {
                wrong.add(c.where() + ": " + e.getMessage() + ": " + c.text());
            }
        }
        assertThat(wrong).as("commands in the docs that fail as written").isEmpty();
    }

    /** The Java code blocks of the docs, each with where it is. */
    static List<Command> javaBlocks() throws IOException {
        List<Command> blocks = new ArrayList<>();
        for (Path doc : docs()) {
            String text = Files.readString(doc);
            Matcher m = FENCE.matcher(text);
            while (m.find()) {
                if (!m.group(1).equals("java")) continue;
                String before = text.substring(0, m.start()).strip();
                Matcher pkg = Pattern.compile("<!-- docs-check: package ([\\w.]+) -->$").matcher(before);
                String code = pkg.find() ? "//package " + pkg.group(1) + "\n" + m.group(2) : m.group(2);
                blocks.add(new Command(doc + ":" + (text.substring(0, m.start()).split("\n", -1).length), code));
            }
        }
        return blocks;
    }

    /** What the docs' statements may use without declaring it: what the text around them gives. */
    private static final String GIVEN = """
            TriangleMesh mesh; Scene2D shapes2d; KdTree tree; Traverser traverser; Ray ray; Hit hit;
            double[] q; double ox, oy, oz, dx, dy, dz, x, y, z, radius;
            void visit(int primitive) { }
            static class MyBuilder extends org.kdtree.examples.CentreMidpointBuilder { }
            """;

    @Test void everyJavaBlockInTheDocsCompiles(@TempDir Path dir) throws IOException {
        List<Command> blocks = javaBlocks();
        assertThat(blocks).as("Java blocks in the docs").hasSizeGreaterThan(10);
        StringBuilder imports = new StringBuilder("package docs;\nimport java.nio.file.*;\nimport java.util.*;\n");
        try (Stream<Path> pkgs = Files.list(Path.of("src/main/java/org/kdtree"))) {
            pkgs.filter(Files::isDirectory).sorted().forEach(p -> imports.append("import org.kdtree.").append(p.getFileName()).append(".*;\n"));
        }
        imports.append("import org.kdtree.kdtree.BuildNode;\n");
        imports.append("import org.kdtree.contract.*;\n");
        List<String> wrong = new ArrayList<>();
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        int n = 0;
        for (Command b : javaBlocks()) {
            String code = b.text().replaceAll("= \\.\\.\\.;", "= null;");
            String pkg = "docs";
            if (code.startsWith("//package ")) {
                pkg = code.substring(10, code.indexOf('\n'));
                code = code.substring(code.indexOf('\n') + 1);
            }
            String unit, name;
            Matcher cls = Pattern.compile("(?m)^(?:public |final |abstract )*class (\\w+)").matcher(code);
            if (cls.find()) {
                name = cls.group(1);
                String body = code.replaceAll("(?m)^package .*$", "");
                unit = body.contains("import ") ? "package docs;\n" + body : imports + body;
            } else if (code.strip().matches("(?s)(@Override |protected |public |private ).*")) {
                name = "Snippet" + n;
                unit = imports + "abstract class " + name + " extends KdTreeBuilder {\n" + code + "\n}\n";
            } else {
                name = "Snippet" + n;
                unit = imports + "class " + name + " {\n" + GIVEN + "void run() throws Exception {\n" + code + "\n}\n}\n";
            }
            if (unit.contains("new MyBuilder()") && !unit.matches("(?s).*class MyBuilder\\b.*"))   // the reader's own builder
                unit += "\nclass MyBuilder extends org.kdtree.examples.CentreMidpointBuilder { }\n";
            unit = unit.replaceFirst("package docs;", "package " + pkg + ";");
            n++;
            String source = unit;
            JavaFileObject file = new SimpleJavaFileObject(java.net.URI.create("string:///" + pkg.replace('.', '/') + "/" + name + ".java"), JavaFileObject.Kind.SOURCE) {
                @Override public CharSequence getCharContent(boolean ignore) {
                    return source;
                }
            };
            StringWriter errors = new StringWriter();
            try (StandardJavaFileManager files = javac.getStandardFileManager(null, null, null)) {
                boolean ok = javac.getTask(errors, files, null, List.of("-d", dir.toString(), "-cp", System.getProperty("java.class.path"),
                        "-proc:none", "-Xlint:none"), null, List.of(file)).call();
                if (!ok) wrong.add(b.where() + ": does not compile:\n" + errors);
            }
        }
        assertThat(wrong).as("Java blocks in the docs that do not compile as written").isEmpty();
    }
}
