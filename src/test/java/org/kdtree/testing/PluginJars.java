package org.kdtree.testing;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;

/** Plug-in jars for tests: a jar whose only content is the services line naming builders, as a student's jar lists its own. */
public final class PluginJars {
    private PluginJars() {
    }

    /** Writes {@code dir/name} listing {@code builderClasses} (on the test class path) in META-INF/services. */
    public static Path listing(Path dir, String name, String... builderClasses) throws IOException {
        Path jar = dir.resolve(name);
        try (OutputStream out = Files.newOutputStream(jar); JarOutputStream j = new JarOutputStream(out)) {
            j.putNextEntry(new JarEntry("META-INF/services/org.kdtree.build.KdTreeBuilder"));
            j.write((String.join("\n", builderClasses) + "\n").getBytes(StandardCharsets.UTF_8));
            j.closeEntry();
        }
        return jar;
    }
}
