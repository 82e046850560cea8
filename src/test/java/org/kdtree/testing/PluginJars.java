package org.kdtree.testing;

import java.io.IOException;
import java.io.OutputStream;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.jar.Attributes;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;

/** Plug-in jars for tests: a jar whose only content is the services line naming builders, as a student's jar lists its own. */
public final class PluginJars {
    private PluginJars() {
    }

    /** Writes {@code dir/name} listing {@code builderClasses} (on the test class path) in META-INF/services. */
    public static Path listing(Path dir, String name, String... builderClasses) throws IOException {
        return student(dir, name, null, builderClasses, null);
    }

    /**
     * Writes {@code dir/name} as a student's jar for a JVM of its own: the manifest naming
     * {@code student} (if not null), the services file listing {@code listed} (none if it is empty), and the class
     * files of {@code listed} and {@code helpers}, copied from the test classes (none if
     * {@code helpers} is null: a jar for this JVM, whose class path has them).
     */
    public static Path student(Path dir, String name, String student, String[] listed, String[] helpers) throws IOException {
        return student(dir, name, student, listed, helpers, java.util.Map.of());
    }

    /** {@link #student(Path, String, String, String[], String[])} with {@code resources} too: entry name to content. */
    public static Path student(Path dir, String name, String student, String[] listed, String[] helpers,
                               java.util.Map<String, String> resources) throws IOException {
        Path jar = dir.resolve(name);
        Manifest m = new Manifest();
        m.getMainAttributes().put(Attributes.Name.MANIFEST_VERSION, "1.0");
        if (student != null) m.getMainAttributes().put(Attributes.Name.IMPLEMENTATION_VENDOR, student);
        try (OutputStream out = Files.newOutputStream(jar); JarOutputStream j = new JarOutputStream(out, m)) {
            if (listed.length > 0 || helpers == null) {
                j.putNextEntry(new JarEntry("META-INF/services/org.kdtree.kdtree.KdTreeBuilder"));
                j.write((String.join("\n", listed) + "\n").getBytes(StandardCharsets.UTF_8));
                j.closeEntry();
            }
            if (helpers != null) {
                for (String c : listed) copyClass(j, c);
                for (String c : helpers) copyClass(j, c);
            }
            for (var r : resources.entrySet()) {
                j.putNextEntry(new JarEntry(r.getKey()));
                j.write(r.getValue().getBytes(StandardCharsets.UTF_8));
                j.closeEntry();
            }
        }
        return jar;
    }

    private static void copyClass(JarOutputStream j, String className) throws IOException {
        String entry = className.replace('.', '/') + ".class";
        try {
            Path file = Path.of(PluginJars.class.getProtectionDomain().getCodeSource().getLocation().toURI()).resolve(entry);
            j.putNextEntry(new JarEntry(entry));
            j.write(Files.readAllBytes(file));
            j.closeEntry();
        } catch (URISyntaxException e) {
            throw new IOException(e);
        }
    }
}
