package org.kdtree.architecture;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.SortedMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * The package structure of docs/architecture.md, checked against the imports of src/main: no
 * cycle between packages, every package in a layer, every use pointing to a lower layer, no room
 * (library, rendering, course, applications: {@link Rooms}) using a higher one; the
 * precision rule of {@code geom.Tolerance}: no tolerance written as a literal anywhere else; one
 * way to write a file; and the node layout known only to the tree's own files.
 */
class ArchitectureTest {
    private static final SortedMap<String, SortedMap<String, Integer>> USES = PackageImports.read();

    @Test void thePackagesFormNoCycle() {
        assertThat(Cycles.of(USES)).as("package cycles").isEmpty();
    }

    @Test void everyPackageHasALayerAndEveryLayerAPackage() {
        Map<String, Integer> layers = Layers.read();
        assertThat(layers.keySet()).as("packages in the layers of " + Layers.DOCUMENT)
                .containsExactlyInAnyOrderElementsOf(USES.keySet());
    }

    /** architecture.md says how many top-level types of src/main are public, counted as here. */
    @Test void theDocumentCountsThePublicTypes() throws java.io.IOException {
        Pattern publicType = Pattern.compile("(?m)^public (final |abstract |sealed )?(class|interface|record|enum) ");
        int all = 0, open = 0;
        for (Path f : SourceFiles.all()) {
            if (f.getFileName().toString().equals("package-info.java")) continue;
            all++;
            if (publicType.matcher(SourceFiles.read(f)).find()) open++;
        }
        assertThat(java.nio.file.Files.readString(Layers.DOCUMENT)).as("the count of public types in " + Layers.DOCUMENT)
                .contains(open + " of the " + all + " top-level");
    }

    /** The README's "What is here" and architecture.md's table name every package of src/main, and no other. */
    @Test void theReadmeAndTheArchitectureTableNameEveryPackage() throws java.io.IOException {
        java.util.Set<String> packages = new java.util.TreeSet<>(Layers.read().keySet());
        String readme = java.nio.file.Files.readString(Path.of("README.md"));
        java.util.Set<String> inReadme = new java.util.TreeSet<>();
        for (Matcher m = Pattern.compile("`src/main/java/org/kdtree/([a-z0-9]+)`").matcher(readme); m.find(); ) inReadme.add(m.group(1));
        assertThat(inReadme).as("README.md's packages").isEqualTo(packages);
        String doc = java.nio.file.Files.readString(Layers.DOCUMENT);
        java.util.Set<String> inTable = new java.util.TreeSet<>();
        for (Matcher m = Pattern.compile("(?m)^\\| `([a-z0-9]+)` \\|").matcher(doc); m.find(); ) inTable.add(m.group(1));
        assertThat(inTable).as("the package table of " + Layers.DOCUMENT).isEqualTo(packages);
    }

    @Test void everyUseGoesDownTheLayers() {
        Map<String, Integer> layer = Layers.read();
        List<String> wrong = new ArrayList<>();
        USES.forEach((from, targets) -> targets.keySet().forEach(to -> {
            if (layer.containsKey(from) && layer.containsKey(to) && layer.get(to) >= layer.get(from))
                wrong.add(from + " (layer " + (layer.get(from) + 1) + ") uses " + to + " (layer " + (layer.get(to) + 1) + ")");
        }));
        assertThat(wrong).as("uses against the layers of " + Layers.DOCUMENT).isEmpty();
    }

    @Test void everyPackageIsInOneRoom() {
        assertThat(Rooms.indexOfPackage().keySet()).as("packages in the rooms of Rooms.ROOMS")
                .containsExactlyInAnyOrderElementsOf(USES.keySet());
    }

    /** The library never uses rendering, the course or an application; rendering neither of the last two; the course no application. */
    @Test void noRoomUsesAHigherRoom() {
        assertThat(upwardUses(USES)).as("uses from a lower room into a higher one").isEmpty();
    }

    @Test void theRoomCheckFindsALibraryPackageUsingTheCourse() {
        Map<String, Map<String, Integer>> graph = Map.of("kdtree", Map.of("examples", 1), "cli", Map.of("kdtree", 1));
        assertThat(upwardUses(graph)).containsExactly("kdtree (library) uses examples (course)");
    }

    /** A services file is a use no import shows: the library's may name only library classes (the course example is registered by the applications). */
    @Test void theLibrarysServicesFilesNameNoHigherRoom() throws java.io.IOException {
        Path services = Path.of("src/main/resources/META-INF/services");
        Map<String, Integer> room = Rooms.indexOfPackage();
        List<String> wrong = new ArrayList<>();
        if (java.nio.file.Files.isDirectory(services)) try (var files = java.nio.file.Files.list(services)) {
            for (Path f : files.toList())
                for (String line : java.nio.file.Files.readAllLines(f)) {
                    Matcher m = Pattern.compile("^org\\.kdtree\\.([a-z0-9]+)\\.").matcher(line.trim());
                    if (m.find() && room.getOrDefault(m.group(1), 0) > 0) wrong.add(f.getFileName() + " names " + line.trim());
                }
        }
        assertThat(wrong).as("services files of src/main naming course or application classes").isEmpty();
    }

    private static List<String> upwardUses(Map<String, ? extends Map<String, Integer>> uses) {
        Map<String, Integer> room = Rooms.indexOfPackage();
        List<String> wrong = new ArrayList<>();
        uses.forEach((from, targets) -> targets.keySet().forEach(to -> {
            if (room.containsKey(from) && room.containsKey(to) && room.get(to) > room.get(from))
                wrong.add(from + " (" + Rooms.name(room.get(from)) + ") uses " + to + " (" + Rooms.name(room.get(to)) + ")");
        }));
        return wrong;
    }

    /** Each package says what it holds and what it may use, with the layer the document gives it. */
    @Test void everyPackageHasAPackageInfoNamingItsLayer() {
        Map<String, Integer> layer = Layers.read();
        List<String> wrong = new ArrayList<>();
        for (String p : USES.keySet()) {
            Path info = SourceFiles.MAIN.resolve("org/kdtree/" + p + "/package-info.java");
            if (!java.nio.file.Files.exists(info)) wrong.add(info + ": missing");
            else if (layer.containsKey(p) && !SourceFiles.read(info).contains("Layer " + (layer.get(p) + 1)))
                wrong.add(info + ": does not say 'Layer " + (layer.get(p) + 1) + "'");
        }
        assertThat(wrong).isEmpty();
    }

    @Test void theCycleCheckFindsACycle() {
        Map<String, Map<String, Integer>> graph = Map.of("io", Map.of("render", 1), "render", Map.of("scene", 1),
                "scene", Map.of("io", 1), "cli", Map.of("io", 1));
        assertThat(Cycles.of(graph)).singleElement().satisfies(c -> assertThat(c).containsExactlyInAnyOrder("io", "render", "scene"));
    }

    /** Small literals that are not tolerances. */
    private static final java.util.Set<String> NOT_TOLERANCES = java.util.Set.of(
            "SplitMix64.java: 0x1.0p-53",    // 53 random bits to a fraction in [0, 1)
            "Contract.java: 1e-6");          // a contract scene scaled down by a million

    /** Scientific literals of 1e-5 and below, hexadecimal floating-point literals: precision, which has one home. */
    @Test void toleranceLiteralsLiveOnlyInTolerance() {
        Pattern literal = Pattern.compile("\\b(\\d+(\\.\\d*)?[eE]-0*([5-9]|\\d{2,})\\b|0[xX][0-9a-fA-F.]+[pP][-+]?\\d+)");
        List<String> found = new ArrayList<>();
        for (Path file : SourceFiles.all()) {
            if (file.endsWith(Path.of("geom/Tolerance.java"))) continue;
            String code = SourceFiles.code(SourceFiles.read(file));
            Matcher m = literal.matcher(code);
            while (m.find()) if (!NOT_TOLERANCES.contains(file.getFileName() + ": " + m.group())) found.add(file + ": " + m.group());
        }
        assertThat(found).as("tolerance literals outside geom.Tolerance").isEmpty();
    }

    /**
     * Files are written one way, whole or not at all ({@code files.AtomicFile}): no other code
     * opens a file for writing or hands ImageIO a file of its own.
     */
    @Test void filesAreWrittenOnlyByAtomicFile() {
        Pattern writing = Pattern.compile("Files\\.(write|writeString|newBufferedWriter|newOutputStream|copy)\\s*\\("
                + "|new\\s+(FileOutputStream|FileWriter|RandomAccessFile)\\b|ImageIO\\.write\\s*\\([^;]*toFile\\(\\)"
                + "|\\b(BitmapEncoder|VectorGraphicsEncoder)\\.");
        List<String> found = new ArrayList<>();
        for (Path file : SourceFiles.all()) {
            if (file.startsWith(SourceFiles.MAIN.resolve("org/kdtree/files"))) continue;
            Matcher m = writing.matcher(SourceFiles.code(SourceFiles.read(file)));
            while (m.find()) found.add(file + ": " + m.group());
        }
        assertThat(found).as("files written other than by files.AtomicFile").isEmpty();
    }

    /**
     * Only the tree itself knows the node layout ({@code kdtree.Nodes}, {@code KdTree}, the writer
     * and the walkers that count its statistics): all other code, the kd-tree's builders and
     * traversal included, reads nodes through {@code Nodes} (hot loops) or {@code KdTree}'s methods,
     * never by indexing the node array, masking or shifting a word, or asking for a leaf mark.
     */
    @Test void nodeWordsAreDecodedOnlyByTheTree() {
        List<String> found = new ArrayList<>();
        Path kdtree = SourceFiles.MAIN.resolve("org/kdtree/kdtree");
        List<Path> layout = List.of(kdtree.resolve("Nodes.java"), kdtree.resolve("KdTree.java"),
                kdtree.resolve("KdTreeWriter.java"), kdtree.resolve("KdTreeStats.java"), kdtree.resolve("TreeVisitor.java"));
        for (Path file : SourceFiles.all()) {
            if (layout.contains(file)) continue;
            for (String d : NodeDecoding.in(SourceFiles.code(SourceFiles.read(file)))) found.add(file + ": " + d);
        }
        assertThat(found).as("node words decoded outside the tree's own files (read them with kdtree.Nodes)").isEmpty();
    }

    /**
     * The kd-tree and the bounding volume hierarchy are siblings, picked by name in one layer
     * ({@code spec}): below it no code names a structure but its own, and nowhere does code ask
     * which structure it holds by a kind string or an {@code isBvh}; {@code instanceof} on a
     * structure or its builder stands only where one is picked (spec) and where the workbench
     * picks the one view of a structure ({@code gui.Built.of}).
     */
    @Test void structuresAreSiblingsNamedOnlyWhereOneIsPicked() {
        assertThat(siblingViolations(SourceFiles.all())).as("structures named, asked or tested below the picking layer").isEmpty();
    }

    /** The check above finds what the issue that made the structures siblings listed (on sources as they were). */
    @Test void theSiblingCheckFindsWhatItForbids() {
        assertThat(siblingViolations("accel", "import org.kdtree.bvh.BvhBuilder; class Setting { Object b = new BvhBuilder(); }")).isNotEmpty();
        assertThat(siblingViolations("bvh", "class BvhTraverser { boolean c = org.kdtree.kdtree.KdTree.class != null; }")).isNotEmpty();
        assertThat(siblingViolations("render", "class RenderJob { String k(S s) { return s.kind().equals(\"kd-tree\") ? \"tree\" : s.kind(); } }")).isNotEmpty();
        assertThat(siblingViolations("cli", "class StatsCommand { void f(Object built) { if (built instanceof KdTree kd) { } } }")).isNotEmpty();
        assertThat(siblingViolations("gui", "record Built(KdTree tree, Bvh bvh) { boolean isBvh() { return bvh != null; } }")).isNotEmpty();
        assertThat(siblingViolations("kdtree", "final class KdTree { String kind() { return \"kd-tree\"; } }")).isEmpty();
    }

    private static final java.util.Set<String> BELOW_THE_STRUCTURES = java.util.Set.of("limits", "geom", "files", "shape", "accel", "generate");
    private static final Pattern ANY_STRUCTURE = Pattern.compile("\\b(KdTree|KdTreeBuilder|Bvh|BvhBuilder)\\b");
    private static final Pattern A_BVH = Pattern.compile("\\b(Bvh|BvhBuilder)\\b"), A_KD_TREE = Pattern.compile("\\b(KdTree|KdTreeBuilder)\\b");
    private static final Pattern ASKED = Pattern.compile("\\bisBvh\\b|\\bbuildsBvh\\b|kind\\s*\\(\\s*\\)\\s*\\.\\s*equals");
    private static final Pattern KIND_STRING = Pattern.compile("\\.equals\\(\\s*\"(kd-tree|bvh)\"\\s*\\)|\"(kd-tree|bvh)\"\\s*\\.\\s*equals");
    private static final Pattern TESTED = Pattern.compile("instanceof\\s+(KdTree|Bvh|KdTreeBuilder|BvhBuilder)\\b");

    private static List<String> siblingViolations(List<Path> files) {
        List<String> found = new ArrayList<>();
        for (Path f : files) {
            String source = SourceFiles.read(f);
            String where = f.toString().replace('\\', '/');
            boolean viewPicker = where.endsWith("gui/Built.java");
            for (String v : siblingViolations(SourceFiles.packageOf(source), source))
                if (!(viewPicker && v.startsWith("instanceof"))) found.add(f + ": " + v);
        }
        return found;
    }

    private static List<String> siblingViolations(String pkg, String source) {
        List<String> found = new ArrayList<>();
        String code = SourceFiles.code(source);
        Pattern foreign = BELOW_THE_STRUCTURES.contains(pkg) ? ANY_STRUCTURE : pkg.equals("kdtree") ? A_BVH : pkg.equals("bvh") ? A_KD_TREE : null;
        if (foreign != null) for (Matcher m = foreign.matcher(code); m.find(); ) found.add("names " + m.group());
        for (Matcher m = ASKED.matcher(code); m.find(); ) found.add("asks " + m.group());
        for (Matcher m = KIND_STRING.matcher(source); m.find(); ) found.add("compares " + m.group());
        if (!pkg.equals("spec")) for (Matcher m = TESTED.matcher(code); m.find(); ) found.add(m.group());
        return found;
    }

    /** File kinds are known in one place, {@code io.FileKind}: no other code tests a file name's extension. */
    @Test void fileKindsAreKnownOnlyToTheirRegistry() {
        Pattern extension = Pattern.compile("\"\\.(obj|json|scene2d|mtl)\"");
        List<String> found = new ArrayList<>();
        for (Path f : SourceFiles.all()) {
            if (f.endsWith(Path.of("io", "FileKind.java"))) continue;
            for (Matcher m = extension.matcher(SourceFiles.read(f)); m.find(); ) found.add(f + ": " + m.group());
        }
        assertThat(found).as("file extensions tested outside io.FileKind").isEmpty();
    }

    /** The check above on the hand decodings it replaced (the traversal's and the point queries'), and on their fix. */
    @Test void theNodeCheckFindsHandDecoding() {
        String generic = """
                nodes = tree.nodeArray(); mark = tree.leafMark(); shift = tree.axisBits();
                int w = nodes[3 * node];
                while ((w & mark) != mark) { int axis = w & mark, far = w >>> shift; }
                """;
        assertThat(NodeDecoding.in(generic)).contains("leafMark", "nodes[", "& mark", ">>> shift");
        String mesh = """
                this.nodes = tree.nodeArray();
                int[] nodes = this.nodes;
                int w = nodes[3 * node];
                while ((w & 3) != 3) w = nodes[3 * (node + 1)];
                for (int r = nodes[3 * node + 1], end = r + (w >>> 2); r < end; r++) { }
                """;
        assertThat(NodeDecoding.in(mesh)).contains("nodes[", "w &", "w >>>");
        String points = """
                int bits = points.tree().axisBits();
                int w = Nodes.word(nodes, node);
                if ((w & 3) == 3) scan(w >>> bits);
                """;
        assertThat(NodeDecoding.in(points)).contains("w &", ">>> bits");
        String now = """
                bits = tree.axisBits(); nodes = tree.nodeArray();
                int w = Nodes.word(nodes, node);
                while (!Nodes.isLeaf(w, bits) && sp > 0) node = Nodes.rightChild(w, bits);
                """;
        assertThat(NodeDecoding.in(now)).isEmpty();
    }

    /** Cycles in a graph: its strongly connected components of more than one node (Tarjan). */
    static final class Cycles {
        private final Map<String, ? extends Map<String, Integer>> graph;
        private final Map<String, Integer> index = new HashMap<>(), low = new HashMap<>();
        private final List<String> stack = new ArrayList<>();
        private final List<List<String>> cycles = new ArrayList<>();

        private Cycles(Map<String, ? extends Map<String, Integer>> graph) {
            this.graph = graph;
        }

        static List<List<String>> of(Map<String, ? extends Map<String, Integer>> graph) {
            Cycles c = new Cycles(graph);
            for (String node : graph.keySet()) if (!c.index.containsKey(node)) c.visit(node);
            return c.cycles;
        }

        private void visit(String node) {
            index.put(node, index.size());
            low.put(node, index.get(node));
            stack.add(node);
            Map<String, Integer> targets = graph.get(node);
            for (String next : targets == null ? java.util.Set.<String>of() : targets.keySet()) {
                if (!index.containsKey(next)) {
                    visit(next);
                    low.put(node, Math.min(low.get(node), low.get(next)));
                } else if (stack.contains(next)) {
                    low.put(node, Math.min(low.get(node), index.get(next)));
                }
            }
            if (low.get(node).equals(index.get(node))) {
                List<String> component = new ArrayList<>();
                String top;
                do {
                    top = stack.remove(stack.size() - 1);
                    component.add(top);
                } while (!top.equals(node));
                if (component.size() > 1) cycles.add(component);
            }
        }
    }
}
