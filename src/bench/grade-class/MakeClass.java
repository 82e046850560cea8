import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.jar.Attributes;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import javax.tools.ToolProvider;

/**
 * A class of students' jars for timing grade-class: each as the starter project makes it
 * (builder.MyBuilder, named my-builder, the student in the manifest), in a mix of ten kinds that
 * repeats, one in ten of them hung or too slow:
 * five sound builders (midpoint planes at three leaf sizes, an object median, a binned SAH),
 * a plane outside the voxel, an exception, System.exit, not a jar or a memory hoarder,
 * and a findPlane that never returns or a naive one that sorts inside its loop, O(n^2 log n) a node, too slow for the build deadline on big scenes.
 *
 * <p>Run from the checkout, after {@code mvn package}:
 * {@code java -cp target/kdtree.jar src/bench/grade-class/MakeClass.java class100 100}
 */
public class MakeClass {
    private static final String MIDPOINT_CYCLE =
            "int a = n.depth() % n.dimension(); return new SplitPlane(a, n.voxel().min(a) + 0.5 * n.voxel().extent(a));";
    private static final String LONGEST = """
            int a = 0; for (int i = 1; i < n.dimension(); i++) if (n.voxel().extent(i) > n.voxel().extent(a)) a = i;
            """;
    private static final String MIDPOINT_LONGEST = LONGEST + "return new SplitPlane(a, n.voxel().min(a) + 0.5 * n.voxel().extent(a));";
    private static final String OBJECT_MEDIAN = LONGEST + """
            double[] m = new double[n.size()];
            for (int j = 0; j < m.length; j++) m[j] = 0.5 * (n.clippedMin(j, a) + n.clippedMax(j, a));
            java.util.Arrays.sort(m);
            return new SplitPlane(a, m[m.length / 2]);
            """;
    private static final String BINNED_SAH = """
            double best = Double.POSITIVE_INFINITY; int ba = 0; double bp = n.voxel().min(0) + 0.5 * n.voxel().extent(0);
            for (int a = 0; a < n.dimension(); a++) {
                double lo = n.voxel().min(a), w = n.voxel().extent(a);
                if (!(w > 0)) continue;
                for (int b = 1; b < 8; b++) {
                    double p = lo + w * b / 8; int l = 0, r = 0;
                    for (int j = 0; j < n.size(); j++) { if (n.clippedMin(j, a) < p) l++; if (n.clippedMax(j, a) > p) r++; }
                    double cost = l * (double) b + r * (double) (8 - b);
                    if (cost < best) { best = cost; ba = a; bp = p; }
                }
            }
            return new SplitPlane(ba, bp);
            """;
    private static final String OUTSIDE = "return new SplitPlane(0, n.voxel().min(0) - 1);";
    private static final String THROWS = "if (n.depth() == 3) { int[] a = new int[2]; return new SplitPlane(a[n.depth()], 0); } " + MIDPOINT_CYCLE;
    private static final String EXITS = "System.exit(3); return null;";
    private static final String HOARDS = "java.util.List<long[]> kept = new java.util.ArrayList<>(); while (true) kept.add(new long[1 << 20]);";
    private static final String HANGS = "double s = 1; while (s > 0) s += Math.sqrt(s); return null;";
    /** A naive search that sorts inside its loop: every primitive's lower bound a candidate, O(n^2 log n) a node. */
    private static final String TOO_SLOW = """
            double best = Double.POSITIVE_INFINITY; int ba = 0; double bp = n.voxel().min(0) + 0.5 * n.voxel().extent(0);
            for (int a = 0; a < n.dimension(); a++)
                for (int k = 0; k < n.size(); k++) {
                    double p = n.clippedMin(k, a);
                    double[] lo = new double[n.size()], hi = new double[n.size()];
                    for (int j = 0; j < n.size(); j++) { lo[j] = n.clippedMin(j, a); hi[j] = n.clippedMax(j, a); }
                    java.util.Arrays.sort(lo); java.util.Arrays.sort(hi);
                    int l = 0, r = 0;
                    while (l < lo.length && lo[l] < p) l++;
                    while (r < hi.length && hi[hi.length - 1 - r] > p) r++;
                    double cost = l * (p - n.voxel().min(a)) + r * (n.voxel().max(a) - p);
                    if (p > n.voxel().min(a) && p < n.voxel().max(a) && cost < best) { best = cost; ba = a; bp = p; }
                }
            return new SplitPlane(ba, bp);
            """;


    /** One kind of student: its findPlane and the leaf size its terminate stops at. */
    record Kind(String name, String findPlane, int leafSize) {
    }

    static List<Kind> kinds(int decade) {
        return List.of(new Kind("midpoint", MIDPOINT_CYCLE, 2), new Kind("longest-axis", MIDPOINT_LONGEST, 1),
                new Kind("big-leaves", MIDPOINT_CYCLE, 4), new Kind("object-median", OBJECT_MEDIAN, 2),
                new Kind("binned-sah", BINNED_SAH, 2), new Kind("plane-outside", OUTSIDE, 2),
                new Kind("throws", THROWS, 2), new Kind("exits", EXITS, 2),
                decade % 2 == 0 ? new Kind("not-a-jar", null, 0) : new Kind("hoards", HOARDS, 2),
                decade % 2 == 0 ? new Kind("hangs", HANGS, 2) : new Kind("too-slow", TOO_SLOW, 2));
    }

    public static void main(String[] args) throws IOException {
        if (args.length < 1 || args.length > 2) {
            System.err.println("usage: java -cp target/kdtree.jar src/bench/grade-class/MakeClass.java FOLDER [STUDENTS (default 100)]");
            System.exit(2);
        }
        int students = args.length > 1 && args[1].matches("[1-9][0-9]{0,4}") ? Integer.parseInt(args[1]) : args.length > 1 ? -1 : 100;
        if (students < 0) {
            System.err.println("error: STUDENTS " + args[1] + ": give a whole number from 1 to 99999");
            System.exit(2);
        }
        Path out = Files.createDirectories(Path.of(args[0]));
        Path work = Files.createTempDirectory("make-class-");
        java.util.Map<String, Path> compiled = new java.util.HashMap<>();
        for (int i = 0; i < students; i++) {
            Kind k = kinds(i / 10).get(i % 10);
            Path jar = out.resolve(String.format("s%03d-%s.jar", i + 1, k.name()));
            if (k.findPlane() == null) {
                Files.writeString(jar, "my notes, not a jar");
                continue;
            }
            Path classes = compiled.computeIfAbsent(k.name(), name -> compile(work.resolve(name), k));
            write(jar, classes, "Student " + (i + 1));
        }
        System.out.println(students + " jars in " + out);
    }

    private static Path compile(Path dir, Kind k) {
        try {
            Path src = Files.createDirectories(dir.resolve("builder")).resolve("MyBuilder.java");
            Files.writeString(src, """
                    package builder;
                    import org.kdtree.geom.SplitPlane;
                    import org.kdtree.kdtree.BuildContext;
                    import org.kdtree.kdtree.BuildNode;
                    import org.kdtree.kdtree.KdTreeBuilder;
                    public class MyBuilder extends KdTreeBuilder {
                        @Override public String name() { return "my-builder"; }
                        @Override protected boolean terminate(BuildContext c, BuildNode n) { return n.size() <= %d || n.depth() >= c.depthCap(); }
                        @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) { %s }
                    }
                    """.formatted(k.leafSize(), k.findPlane()));
            Path classes = Files.createDirectories(dir.resolve("classes"));
            int rc = ToolProvider.getSystemJavaCompiler().run(null, null, null, "--release", "17", "-d", classes.toString(),
                    "-cp", System.getProperty("java.class.path"), src.toString());
            if (rc != 0) throw new IllegalStateException(k.name() + ": does not compile");
            return classes;
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private static void write(Path jar, Path classes, String student) throws IOException {
        Manifest m = new Manifest();
        m.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        m.getMainAttributes().putValue("Implementation-Vendor", student);
        try (OutputStream o = Files.newOutputStream(jar); JarOutputStream j = new JarOutputStream(o, m)) {
            j.putNextEntry(new JarEntry("META-INF/services/org.kdtree.kdtree.KdTreeBuilder"));
            j.write("builder.MyBuilder\n".getBytes(StandardCharsets.UTF_8));
            j.putNextEntry(new JarEntry("builder/MyBuilder.class"));
            j.write(Files.readAllBytes(classes.resolve("builder/MyBuilder.class")));
        }
    }
}
