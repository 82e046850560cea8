package org.kdtree.testing;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.jar.Attributes;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import javax.tools.ToolProvider;

/**
 * A student's jar as the starter project makes it: {@code builder.MyBuilder}, named by
 * {@code name()}, compiled here from source (so that its class is on no class path of the
 * tests: two students' jars hold two different classes of one name).
 */
public final class StudentJars {
    private StudentJars() {
    }

    /**
     * Compiles a median-plane {@code builder.MyBuilder} named {@code builderName} into {@code dir/jarName}.
     *
     * @param leafSize the leaf size it stops at (so two students' builders differ)
     * @param findPlaneBody the body of findPlane, or null for a midpoint cut
     * @param manifest extra manifest attributes (name, value pairs)
     * @return the jar
     * @throws IOException if the jar cannot be written or the source does not compile
     */
    public static Path compile(Path dir, String jarName, String builderName, int leafSize, String findPlaneBody, String... manifest)
            throws IOException {
        Path work = Files.createTempDirectory(dir, "src-");
        Path src = Files.createDirectories(work.resolve("builder")).resolve("MyBuilder.java");
        String body = findPlaneBody != null ? findPlaneBody
                : "int a = n.depth() % n.dimension(); return new SplitPlane(a, n.voxel().min(a) + 0.5 * n.voxel().extent(a));";
        Files.writeString(src, """
                package builder;
                import org.kdtree.kdtree.BuildContext;
                import org.kdtree.kdtree.BuildNode;
                import org.kdtree.kdtree.KdTreeBuilder;
                import org.kdtree.geom.SplitPlane;
                public class MyBuilder extends KdTreeBuilder {
                    @Override public String name() { return "%s"; }
                    @Override protected boolean terminate(BuildContext c, BuildNode n) { return n.size() <= %d || n.depth() >= c.depthCap(); }
                    @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) { %s }
                }
                """.formatted(builderName, leafSize, body));
        Path classes = Files.createDirectories(work.resolve("classes"));
        int rc = ToolProvider.getSystemJavaCompiler().run(null, null, null, "-d", classes.toString(),
                "-cp", System.getProperty("java.class.path"), src.toString());
        if (rc != 0) throw new IOException("the student's source does not compile");
        Path jar = dir.resolve(jarName);
        Manifest m = new Manifest();
        m.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        for (int i = 0; i + 1 < manifest.length; i += 2) m.getMainAttributes().putValue(manifest[i], manifest[i + 1]);
        try (OutputStream out = Files.newOutputStream(jar); JarOutputStream j = new JarOutputStream(out, m)) {
            j.putNextEntry(new JarEntry("META-INF/services/org.kdtree.kdtree.KdTreeBuilder"));
            j.write("builder.MyBuilder\n".getBytes(StandardCharsets.UTF_8));
            j.closeEntry();
            j.putNextEntry(new JarEntry("builder/MyBuilder.class"));
            j.write(Files.readAllBytes(classes.resolve("builder/MyBuilder.class")));
            j.closeEntry();
        }
        return jar;
    }
}
