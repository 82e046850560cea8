package org.kdtree.spec;

import java.io.IOException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.zip.ZipException;
import java.util.zip.ZipFile;
import org.kdtree.kdtree.KdTreeBuilder;

/**
 * A plug-in jar checked before its builders are looked for, so that a wrong file is named as
 * such: a path that is not a readable zip, or a jar that lists no builder, is told what to do in
 * one line (which file to add to the jar, and what line to put in it).
 */
final class PluginJar {
    /** The service file a plug-in lists its builders in. */
    static final String SERVICES = "META-INF/services/" + KdTreeBuilder.class.getName();

    private PluginJar() {
    }

    /** {@return the jar's URL, once it is known to be a readable zip} */
    static URL open(Path jar) {
        try (ZipFile zip = new ZipFile(jar.toFile())) {
            zip.size();
            return jar.toUri().toURL();
        } catch (ZipException notZip) {
            throw new IllegalArgumentException(jar + ": not a jar (zip) file");
        } catch (AccessDeniedException | MalformedURLException e) {
            throw new IllegalArgumentException(jar + ": cannot be read (" + e.getMessage() + ")");
        } catch (IOException e) {
            throw new IllegalArgumentException(jar + ": cannot be read as a jar ("
                    + (Files.isReadable(jar) ? e.getMessage() : "no permission to read it") + ")");
        }
    }

    /** {@return whether the jar has the service file}; it was opened before, so it is a zip. */
    static boolean listsBuilders(Path jar) {
        try (ZipFile zip = new ZipFile(jar.toFile())) {
            return zip.getEntry(SERVICES) != null;
        } catch (IOException e) {
            return false;
        }
    }

    /** {@return the class names the jar's own service file lists}, none if it has none or cannot be read. */
    static Set<String> listedClasses(Path jar) {
        Set<String> names = new HashSet<>();
        try (ZipFile zip = new ZipFile(jar.toFile())) {
            var entry = zip.getEntry(SERVICES);
            if (entry == null) return names;
            try (var in = zip.getInputStream(entry)) {
                for (String line : new String(in.readAllBytes(), StandardCharsets.UTF_8).split("\\R")) {
                    String name = line.replaceFirst("#.*", "").strip();
                    if (!name.isEmpty()) names.add(name);
                }
            }
        } catch (IOException e) {
            return names;
        }
        return names;
    }

    /**
     * What to add to a jar that lists no builder ({@code which}: "the jar", "your builder's
     * jar"): the service file, and its line, the one builder class of the jar if there is exactly one.
     */
    static String missingServices(Path jar, String which) {
        List<String> builders = builderClasses(jar);
        String line = builders.size() == 1 ? builders.get(0) : "the class name of your builder (e.g. com.example.MyBuilder)";
        return "add the file " + SERVICES + " to " + which + ", with one line: " + line;
    }

    /** The public, concrete classes of the jar that extend KdTreeBuilder (not initialised, only looked at). */
    private static List<String> builderClasses(Path jar) {
        List<String> found = new ArrayList<>();
        try (ZipFile zip = new ZipFile(jar.toFile());
             URLClassLoader loader = new URLClassLoader(new URL[] {jar.toUri().toURL()}, PluginJar.class.getClassLoader())) {
            for (var entry : Collections.list(zip.entries())) {
                String n = entry.getName();
                if (!n.endsWith(".class") || n.contains("$") || n.endsWith("module-info.class")) continue;
                String name = n.substring(0, n.length() - ".class".length()).replace('/', '.');
                if (isBuilder(name, loader)) found.add(name);
            }
        } catch (IOException e) {
            return List.of();
        }
        return found;
    }

    private static boolean isBuilder(String name, ClassLoader loader) {
        try {
            Class<?> c = Class.forName(name, false, loader);
            return KdTreeBuilder.class.isAssignableFrom(c) && !java.lang.reflect.Modifier.isAbstract(c.getModifiers());
        } catch (ClassNotFoundException | LinkageError unusable) {
            return false; // a class that cannot even be looked at is no builder to name
        }
    }
}
