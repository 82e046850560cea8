package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.PrintStream;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
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
 * {@code a|b}) parses as written, and the project's files it names exist.
 *
 * <p>Every such command that can run on a fresh machine is run ({@link #everyDocsCommandThatCanRunHereRuns}),
 * in-process, its outputs in a temporary folder, and must succeed and write what the docs say it
 * writes. What cannot run here is said per command: a synopsis (placeholders) and a command that
 * opens the workbench or grades a class in bubblewrap boxes are checked against the parser only;
 * {@code bunny.obj} (the reader's own copy of the Stanford bunny, which the figures use and the
 * project does not ship) is replaced by a bundled mesh, the starter's plug-in jar by one compiled here, and the slow studies and
 * renders run with a stated reduction ({@link #REDUCTIONS}).
 *
 * <p>Every Java code block compiles against the library as a user's code would (outside its
 * packages): a whole class as it stands, a method as a builder's, statements in a method whose
 * class declares what the surrounding text gives (a {@code mesh}, a {@code tree}, ...;
 * {@code ...} is what the reader has). A whole class with a {@code main} is also run. The
 * README's example is also built and run from an empty folder by {@code .ci/readme-check}.
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
                    || a.contains("<") || a.equals("OPTIONS") || a.matches(".*\\b[A-Z][A-Z_]{2,}\\b.*") && !a.startsWith("$") && !a.endsWith(".jar"))
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
                if (outsideTheProject(a)) wrong.add(c.where() + ": " + a + " is outside the project (a clone has only its own files): " + c.text());
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

    /** A path a clone does not have: above it, under a folder variable, or absolute (but for a scratch file in /tmp). */
    static boolean outsideTheProject(String arg) {
        return arg.startsWith("../") || arg.matches("\\$\\{?[A-Z_]+}?/.*") || arg.startsWith("/") && !arg.startsWith("/tmp/");
    }

    /** Issue 46, item 3: no doc, nor the build, names a file of the machine it was written on. */
    @Test void noDocNorTheBuildNamesAMachinesFiles() throws IOException {
        List<String> found = new ArrayList<>();
        List<Path> files = new ArrayList<>(docs());
        files.add(Path.of("pom.xml"));
        Pattern machine = Pattern.compile("\\.\\./shared|/usr/lib/jvm|/work/|/root/|\\$MESHES");
        for (Path f : files) {
            String[] lines = Files.readString(f).split("\n", -1);
            for (int i = 0; i < lines.length; i++)
                if (machine.matcher(lines[i]).find()) found.add(f + ":" + (i + 1) + ": " + lines[i].strip());
        }
        assertThat(found).as("lines naming files outside the project").isEmpty();
    }

    /** Options whose value is a file the command writes: run in the temporary folder. */
    private static final List<String> OUTPUTS = List.of("-o", "--out", "--csv", "--chart", "--hits", "--markdown", "--save-tree");

    /**
     * The mesh that stands in for {@code bunny.obj} (the reader's copy of the Stanford bunny, not in
     * the project): the bundled OBJ of 21 triangles, so that the benchmark's two million rays and
     * its brute-force check take a second, not half a minute.
     */
    private static final String MESH_SUBSTITUTE = "scenes/meshes/mtl-demo.obj";

    /**
     * Commands too slow to run here whatever their options, with why: the scene itself is the cost.
     */
    private static final Map<String, String> TOO_SLOW = Map.of(
            "scenes/sphereflake.json", "its 1.06 million triangles take about ten seconds to make and build before the first ray "
                    + "(RenderCommandTest and the rendering tests render the smaller bundled scenes): the parser only");

    /**
     * What a docs command runs with here, by command, so that all of them take about a minute on
     * two cores: each value replaces the doc's (or is added). The docs' commands measure for minutes
     * (five timed runs of twenty variants, a million points, a 640 x 480 image); the reduced run
     * still checks what the command writes: the table's rows and columns, the chart, the image.
     */
    static final Map<String, Map<String, String>> REDUCTIONS = Map.of(
            "render", new TreeMap<>(Map.of("--width", "64", "--height", "48", "--spp", "1")),
            "raycast", new TreeMap<>(Map.of("--runs", "1", "--warmup", "0")),   // the benchmark's 2 million rays once, not 7 times
            "tradeoff", new TreeMap<>(Map.of("--runs", "1", "--ray-count", "2000", "--counted-rays", "500")),
            "knn-study", new TreeMap<>(Map.of("--n", "2000", "--query-count", "50", "--runs", "1")),
            "stats", new TreeMap<>(Map.of("--runs", "1", "--warmup", "0")));

    /** What the test did with a docs command: ran it (as what), or checked it against the parser only (why). */
    record Plan(Command command, List<String> args, String how, boolean run) {
    }

    /**
     * How each docs command is exercised here: a synopsis, the workbench and a class's grading are
     * parsed only; every other is run, with the substitutes and reductions said in {@code how}.
     *
     * @param dir   the temporary folder the outputs go to
     * @param plugin the starter's plug-in jar, compiled for the test (registers {@code my-builder})
     */
    static List<Plan> plans(Path dir, Path plugin) throws IOException {
        List<Plan> plans = new ArrayList<>();
        Map<List<String>, String> seen = new java.util.HashMap<>();
        Map<String, String> savedTrees = new java.util.HashMap<>();   // a tree file a docs command saves, where it went here
        for (Command c : commands()) {
            List<String> args = new ArrayList<>(arguments(c.text()));
            if (synopsis(args)) { plans.add(new Plan(c, args, "a synopsis (placeholders): the parser only", false)); continue; }
            List<String> notes = new ArrayList<>();
            for (int i = 0; i < args.size(); i++) {
                String a = args.get(i);
                if (a.matches("\\$\\w+")) { args.set(i, "1"); notes.add(a + " = 1 (the loop's first pass)"); }
                else if (a.equals("bunny.obj")) {
                    args.set(i, MESH_SUBSTITUTE);
                    notes.add(a + " -> " + MESH_SUBSTITUTE);
                } else if (a.endsWith("my-builder-1.0-SNAPSHOT.jar")) {
                    args.set(i, plugin.toString());
                    notes.add("the starter's jar -> one compiled here");
                }
            }
            Matcher cp = Pattern.compile("-cp (\\S*my-builder\\S*\\.jar):").matcher(c.text());
            if (cp.find()) {   // the jar on the class path: the same builders as --plugin gives
                args.addAll(0, List.of("--plugin", plugin.toString()));
                notes.add("-cp " + cp.group(1) + " -> --plugin (one compiled here)");
            }
            String name = args.stream().filter(a -> !a.startsWith("-") && !a.endsWith(".jar")).findFirst().orElse(null);
            if (name == null || name.equals("gui")) {   // no command: the workbench
                plans.add(new Plan(c, args, "opens the workbench: the parser only (GuiCommandTest and the GUI tests open it)", false));
                continue;
            }
            String slow = args.stream().filter(TOO_SLOW::containsKey).map(TOO_SLOW::get).findFirst().orElse(null);
            if (slow != null) { plans.add(new Plan(c, args, slow, false)); continue; }
            if (name.equals("grade-class")) {
                plans.add(new Plan(c, args, "grades a class, a JVM per student in a bubblewrap box: the parser only "
                        + "(ClassGradeCommandTest and ClassGradeSandboxTest run it)", false));
                continue;
            }
            for (Map.Entry<String, String> r : REDUCTIONS.getOrDefault(name, Map.of()).entrySet()) {
                int at = args.indexOf(r.getKey());
                if (at >= 0 && at + 1 < args.size()) args.set(at + 1, r.getValue()); else args.addAll(List.of(r.getKey(), r.getValue()));
                notes.add(r.getKey() + " " + r.getValue());
            }
            String before = seen.putIfAbsent(List.copyOf(args), c.where());
            if (before != null) { plans.add(new Plan(c, args, "the same command as " + before + ": run there", false)); continue; }
            for (int i = 0; i + 1 < args.size(); i++)
                if (OUTPUTS.contains(args.get(i)) && !args.get(i + 1).equals("-")) {
                    Path out = dir.resolve(plans.size() + "-" + Path.of(args.get(i + 1)).getFileName());
                    if (args.get(i).equals("--save-tree")) savedTrees.put(args.get(i + 1), out.toString());
                    args.set(i + 1, out.toString());
                } else if (args.get(i).equals("--tree") && savedTrees.containsKey(args.get(i + 1))) {   // loads what a command above saved
                    args.set(i + 1, savedTrees.get(args.get(i + 1)));
                }
            if (name.equals("tradeoff") || name.equals("knn-study"))   // their default outputs go to the current folder
                for (String option : List.of("--csv", "--chart"))
                    if (!args.contains(option)) args.addAll(List.of(option, dir.resolve(plans.size() + option.substring(1)
                            + (option.equals("--csv") ? ".csv" : ".png")).toString()));
            plans.add(new Plan(c, args, notes.isEmpty() ? "as written" : String.join(", ", notes), true));
        }
        return plans;
    }

    /**
     * Every docs command that can run on a fresh machine runs, and does what the docs say: exit
     * code 0, no error line, each file it is told to write written (a PNG of the size asked, a CSV
     * of a header and rows), and the one benchmark line of raycast.
     */
    @Test void everyDocsCommandThatCanRunHereRuns(@TempDir Path dir) throws IOException {
        Path plugin = org.kdtree.testing.StudentJars.compile(dir, "my-builder-1.0-SNAPSHOT.jar", "my-builder", 4, null);
        List<Plan> plans = plans(dir, plugin);
        List<String> wrong = new ArrayList<>();
        int ran = 0;
        try {
            for (Plan p : plans) {
                if (!p.run()) {
                    System.out.println("parsed only  " + p.command().where() + ": " + p.how());
                    continue;
                }
                long t0 = System.nanoTime();
                CliRun r = CliRun.of(p.args().toArray(String[]::new));
                ran++;
                System.out.printf(java.util.Locale.ROOT, "ran %5.1f s  %s: %s%n", (System.nanoTime() - t0) / 1e9, p.command().where(), p.how());
                String label = p.command().where() + ": " + String.join(" ", p.args());
                if (r.code() != 0 || r.err().contains("error:")) {
                    wrong.add(label + ": exit " + r.code() + ": " + r.err().strip());
                    continue;
                }
                wrong.addAll(shapeProblems(p.args(), r).stream().map(w -> label + ": " + w).toList());
            }
        } finally {
            org.kdtree.spec.Builders.remove("my-builder");
        }
        assertThat(ran).as("docs commands run").isGreaterThanOrEqualTo(15);
        assertThat(wrong).as("docs commands that fail as written (with the substitutes and reductions said)").isEmpty();
    }

    /** What is wrong with what the command wrote, against what the docs say it writes. */
    private static List<String> shapeProblems(List<String> args, CliRun r) throws IOException {
        List<String> wrong = new ArrayList<>();
        for (int i = 0; i + 1 < args.size(); i++) {
            if (!OUTPUTS.contains(args.get(i)) || args.get(i + 1).equals("-")) continue;
            Path out = Path.of(args.get(i + 1));
            if (!Files.isRegularFile(out) || Files.size(out) == 0) { wrong.add("wrote no " + out.getFileName()); continue; }
            String file = out.toString();
            if (file.endsWith(".png")) {
                java.awt.image.BufferedImage image = javax.imageio.ImageIO.read(out.toFile());
                if (image == null) wrong.add(out.getFileName() + " is not a PNG");
                else if (args.contains("render") && (image.getWidth() != Integer.parseInt(value(args, "--width"))
                        || image.getHeight() != Integer.parseInt(value(args, "--height"))))
                    wrong.add(out.getFileName() + " is " + image.getWidth() + " x " + image.getHeight());
            } else if (file.endsWith(".csv")) {
                List<String> lines = Files.readAllLines(out);
                int columns = lines.get(0).split(",").length;
                if (lines.size() < 2) wrong.add(out.getFileName() + " has no rows");
                for (String line : lines.subList(1, lines.size()))
                    if (line.split(",", -1).length != columns) wrong.add(out.getFileName() + ": a row of another width: " + line);
                if (args.contains("tradeoff") && args.contains("--variants")
                        && lines.size() != 1 + value(args, "--variants").split(",").length)
                    wrong.add(out.getFileName() + " has " + (lines.size() - 1) + " rows for the variants " + value(args, "--variants"));
            }
        }
        if (args.contains("raycast") && !args.contains("--rays")) {   // the benchmark's one line (benchmark-spec.md)
            String[] line = r.out().strip().split("\\s+");
            if (line.length != 13 || !line[0].startsWith("kdtree-")) wrong.add("not the benchmark's line: " + r.out().strip());
            if (args.contains("--verify") && !r.err().contains(" 0 disagree")) wrong.add("the tree and brute force disagree: " + r.err());
        }
        if (args.contains("stats") && !r.out().contains("nodes: ")) wrong.add("no statistics: " + r.out());
        return wrong;
    }

    private static String value(List<String> args, String option) {
        return args.get(args.indexOf(option) + 1);
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

    /**
     * What the docs' statements may use without declaring it: what the text around them gives,
     * made real so that the statements run (a bundled mesh and 2-D scene, a tree of the mesh, a ray
     * from outside it towards its centre).
     */
    private static final String GIVEN = """
            TriangleMesh mesh = uncheckedMesh();
            Scene2D shapes2d = BundledScenes.read2D("clustered-200.scene2d");
            KdTree tree = new SahBuilder().build(mesh);
            Traverser traverser = new Traverser(tree);
            double ox = -2, oy = 0.5, oz = 0.5, dx = 1, dy = 0, dz = 0, x = 0.5, y = 0.5, z = 0.5, radius = 0.05;
            Ray ray = new Ray(3).set(ox, oy, oz, dx, dy, dz);
            Hit hit = new Hit();
            double[] q = {0.5, 0.5, 0.5};
            int visited;
            void visit(int primitive) { visited++; }
            static TriangleMesh uncheckedMesh() {
                try { return org.kdtree.io.PrimitivesReader.readMesh(Path.of("scenes/clustered-spheres.obj")); } catch (java.io.IOException e) { throw new java.io.UncheckedIOException(e); }
            }
            static class MyBuilder extends org.kdtree.examples.CentreMidpointBuilder { }
            """;

    /**
     * Java blocks that compile but are not run here, by a call they make, with why (the others of
     * statements run, each in a class that gives what the text gives; a class with a main runs it).
     */
    private static final Map<String, String> COMPILE_ONLY = Map.of(
            "QualityChecks.cases()", "grades the reader's builder: the whole contract and the quality tier, which the course's "
                    + "example stands-in fails by design (the contract tests and GradeCommandTest run them)");

    /** Why a block is compiled only, or null if it runs. */
    private static String compileOnly(String code) {
        return COMPILE_ONLY.entrySet().stream().filter(e -> code.contains(e.getKey())).map(Map.Entry::getValue).findFirst().orElse(null);
    }

    @Test void everyJavaBlockInTheDocsCompilesAndRunsWhereItCan(@TempDir Path dir) throws Exception {
        List<Command> blocks = javaBlocks();
        assertThat(blocks).as("Java blocks in the docs").hasSizeGreaterThan(10);
        StringBuilder imports = new StringBuilder("package docs;\nimport java.nio.file.*;\nimport java.util.*;\n");
        try (Stream<Path> pkgs = Files.list(Path.of("src/main/java/org/kdtree"))) {
            pkgs.filter(Files::isDirectory).sorted().forEach(p -> imports.append("import org.kdtree.").append(p.getFileName()).append(".*;\n"));
        }
        imports.append("import org.kdtree.kdtree.BuildNode;\n");
        imports.append("import org.kdtree.contract.*;\n");
        Path points = dir.resolve("points.csv");   // the file points.md's reader has
        Files.writeString(points, "0.1,0.2,0.3\n0.5,0.5,0.5\n0.9,0.8,0.7\n0.2,0.9,0.4\n0.6,0.1,0.8\n0.3,0.3,0.9\n0.7,0.6,0.2\n0.4,0.8,0.6\n0.8,0.2,0.1\n");
        List<String> wrong = new ArrayList<>();
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        Path classes = Files.createDirectories(dir.resolve("classes"));
        int n = 0, ran = 0;
        for (Command b : blocks) {
            String code = b.text().replaceAll("= \\.\\.\\.;", "= null;");
            String pkg = "docs";
            if (code.startsWith("//package ")) {
                pkg = code.substring(10, code.indexOf('\n'));
                code = code.substring(code.indexOf('\n') + 1);
            }
            String unit, name;
            boolean statements = false;
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
                statements = true;
                // what the reader has stands in for "...", and the files it names are the test's own
                code = code.replaceAll("(\\w+ \\w+) = null;", "$1 = " + (code.contains("TriangleMesh mesh = null;") ? "uncheckedMesh();" : "null;"))
                        .replace("TriangleMesh mesh = uncheckedMesh();", "mesh = uncheckedMesh();")
                        .replace("Path.of(\"points.csv\")", "Path.of(\"" + points.toString().replace("\\", "/") + "\")")
                        .replace("Path.of(\"cornell.png\")", "Path.of(\"" + dir.resolve("cornell.png").toString().replace("\\", "/") + "\")")
                        .replace("Path.of(\"scenes/cornell-box.json\")", "Path.of(\"" + smallCornellBox(dir).toString().replace("\\", "/") + "\")");
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
                boolean ok = javac.getTask(errors, files, null, List.of("-d", classes.toString(), "-cp", System.getProperty("java.class.path"),
                        "-proc:none", "-Xlint:none"), null, List.of(file)).call();
                if (!ok) { wrong.add(b.where() + ": does not compile:\n" + errors); continue; }
            }
            boolean main = source.contains("public static void main(String[] args)");
            String why = compileOnly(source);
            if (!statements && !main || why != null) {
                System.out.println("compiled     " + b.where() + ": " + (why != null ? why : "a class or a builder's methods, compiled only"));
                continue;
            }
            long t0 = System.nanoTime();
            String failure = run(classes, pkg + "." + name, main);
            ran++;
            System.out.printf(java.util.Locale.ROOT, "ran %5.1f s  %s%n", (System.nanoTime() - t0) / 1e9, b.where());
            if (failure != null) wrong.add(b.where() + ": fails as written: " + failure);
        }
        assertThat(wrong).as("Java blocks in the docs that do not compile or run as written").isEmpty();
        assertThat(ran).as("Java blocks run").isGreaterThanOrEqualTo(8);
        assertThat(Files.exists(dir.resolve("cornell.png"))).as("api.md's render wrote its image").isTrue();
    }

    /** The Cornell box at 64 x 64 and one sample per pixel (the doc's 256 x 256 at four takes seconds): the same scene otherwise. */
    private static Path smallCornellBox(Path dir) throws IOException {
        String json = Files.readString(Path.of("scenes/cornell-box.json")).replaceFirst("\"width\": 256", "\"width\": 64")
                .replaceFirst("\"height\": 256", "\"height\": 64").replaceFirst("\"samplesPerPixel\": 4", "\"samplesPerPixel\": 1");
        assertThat(json).contains("\"width\": 64", "\"height\": 64", "\"samplesPerPixel\": 1");
        return Files.writeString(dir.resolve("cornell-box-64.json"), json);
    }

    /** Runs one compiled block: its class's main (no arguments), or its statements' run(); null if it ran, else why not. */
    private static String run(Path classes, String className, boolean main) throws Exception {
        PrintStream out = System.out;
        try (java.net.URLClassLoader loader = new java.net.URLClassLoader(new java.net.URL[] {classes.toUri().toURL()},
                DocsCommandsTest.class.getClassLoader())) {
            Class<?> c = loader.loadClass(className);
            System.setOut(new PrintStream(java.io.OutputStream.nullOutputStream()));
            if (main) {
                c.getMethod("main", String[].class).invoke(null, (Object) new String[0]);
            } else {
                java.lang.reflect.Constructor<?> k = c.getDeclaredConstructor();
                k.setAccessible(true);
                java.lang.reflect.Method m = c.getDeclaredMethod("run");
                m.setAccessible(true);
                m.invoke(k.newInstance());
            }
            return null;
        } catch (java.lang.reflect.InvocationTargetException e) {
            return e.getCause().toString();
        } finally {
            System.setOut(out);
        }
    }
}
