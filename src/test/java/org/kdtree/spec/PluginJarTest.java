package org.kdtree.spec;

import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.testing.PluginMidpointBuilder;
import org.kdtree.testing.SleepyBuilder;

/** Issue 23: a plug-in that is not a jar is named so; a jar without its services file is told what to add. */
class PluginJarTest {
    private static final String SERVICES = "META-INF/services/org.kdtree.kdtree.KdTreeBuilder";

    @TempDir Path dir;

    /** A jar holding the class files of {@code classes} (from the test class path), and no services file. */
    private Path jarOf(String name, Class<?>... classes) throws IOException {
        Path jar = dir.resolve(name);
        try (OutputStream out = Files.newOutputStream(jar); JarOutputStream j = new JarOutputStream(out)) {
            j.putNextEntry(new JarEntry("README.txt"));
            j.closeEntry();
            for (Class<?> c : classes) {
                String entry = c.getName().replace('.', '/') + ".class";
                j.putNextEntry(new JarEntry(entry));
                try (var in = c.getClassLoader().getResourceAsStream(entry)) {
                    in.transferTo(j);
                }
                j.closeEntry();
            }
        }
        return jar;
    }

    @Test void aFileThatIsNotAJarIsNamedAsSuch() throws IOException {
        Path notes = Files.writeString(dir.resolve("notes.jar"), "my notes, not a jar\n");
        assertThatThrownBy(() -> Builders.loadPlugins(notes)).isInstanceOf(IllegalArgumentException.class)
                .hasMessage(notes + ": not a jar (zip) file");
        Path text = Files.writeString(dir.resolve("notes.txt"), "");
        assertThatThrownBy(() -> Builders.loadPlugins(text)).hasMessage(text + ": not a jar (zip) file");
        Files.copy(notes, Files.createDirectory(dir.resolve("folder")).resolve("bad.jar"));
        Path bad = dir.resolve("folder/bad.jar");
        assertThatThrownBy(() -> Builders.loadPlugins(dir.resolve("folder"))).hasMessage(bad + ": not a jar (zip) file");
    }

    @Test void aJarWithOneBuilderAndNoServicesFileIsToldTheLineToAdd() throws IOException {
        Path jar = jarOf("student.jar", PluginMidpointBuilder.class);
        assertThatThrownBy(() -> Builders.loadPlugins(jar)).isInstanceOf(IllegalArgumentException.class)
                .hasMessage(jar + ": the jar lists no builder; add the file " + SERVICES
                        + " to the jar, with one line: " + PluginMidpointBuilder.class.getName());
    }

    @Test void aJarWithNoneOrSeveralBuildersIsToldWhatTheLineIs() throws IOException {
        String line = "the class name of your builder (e.g. com.example.MyBuilder)";
        Path none = jarOf("none.jar");
        assertThatThrownBy(() -> Builders.loadPlugins(none))
                .hasMessage(none + ": the jar lists no builder; add the file " + SERVICES + " to the jar, with one line: " + line);
        Path two = jarOf("two.jar", PluginMidpointBuilder.class, SleepyBuilder.class);
        assertThatThrownBy(() -> Builders.loadPlugins(two))
                .hasMessage(two + ": the jar lists no builder; add the file " + SERVICES + " to the jar, with one line: " + line);
    }

    /**
     * A builder compiled for a newer Java than the one running (its class file's major version
     * raised, as javac --release 25 writes it): named so, with what to do, not a stack trace.
     */
    @Test void aBuilderCompiledForANewerJavaIsNamedWithTheFix() throws Exception {
        Path src = Files.createDirectories(dir.resolve("src/student")), classes = Files.createDirectories(dir.resolve("classes"));
        Files.writeString(src.resolve("Future.java"), "package student;\n"
                + "public class Future extends org.kdtree.kdtree.MedianPlaneBuilder {\n"
                + "    @Override public String name() { return \"future\"; }\n}\n");
        int compiled = javax.tools.ToolProvider.getSystemJavaCompiler().run(null, null, null, "--release", "17",
                "-cp", System.getProperty("java.class.path"), "-d", classes.toString(), src.resolve("Future.java").toString());
        org.assertj.core.api.Assertions.assertThat(compiled).isZero();
        Path classFile = classes.resolve("student/Future.class");
        byte[] bytes = Files.readAllBytes(classFile);
        int newer = Runtime.version().feature() + 45;    // the class file version of the Java after this one
        bytes[6] = 0;
        bytes[7] = (byte) newer;
        Path jar = dir.resolve("future.jar");
        try (OutputStream out = Files.newOutputStream(jar); JarOutputStream j = new JarOutputStream(out)) {
            j.putNextEntry(new JarEntry("student/Future.class"));
            j.write(bytes);
            j.closeEntry();
            j.putNextEntry(new JarEntry(SERVICES));
            j.write("student.Future\n".getBytes(java.nio.charset.StandardCharsets.UTF_8));
            j.closeEntry();
        }
        assertThatThrownBy(() -> Builders.loadPlugins(jar))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessageStartingWith(jar + ": a builder class was compiled for a newer Java than this one runs")
                .hasMessageContaining("class file version " + newer)
                .hasMessageEndingWith("compile it for Java " + Runtime.version().feature() + " (maven.compiler.release, or javac --release)");
    }
}
