package org.kdtree.spec;

import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;
import java.util.Set;
import java.util.function.Supplier;
import org.kdtree.accel.Setting;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.kdtree.MedianPlaneBuilder;
import org.kdtree.kdtree.ObjectMedianBuilder;
import org.kdtree.kdtree.SahBuilder;
import org.kdtree.kdtree.SlidingMidpointBuilder;

/**
 * The builders known by name to the command line and the workbench: the library's own, then
 * every builder that a jar on the class path lists in
 * {@code META-INF/services/org.kdtree.kdtree.KdTreeBuilder} (found with {@link ServiceLoader};
 * each needs a public no-argument constructor and is known by its {@link KdTreeBuilder#name()}).
 * So a student's builder joins them by being on the class path, with no code of the library
 * naming it; {@link #loadPlugins} adds those of a jar (or a folder of jars) named at run time,
 * {@link #register} one from code.
 */
public final class Builders {
    private static final Map<String, Supplier<? extends KdTreeBuilder>> BY_NAME = new LinkedHashMap<>();
    /** Each registered builder's setting rows, asked once (a plug-in's constructor runs once for them, not at every look). */
    private static final Map<String, List<Setting<?>>> ROWS = new java.util.HashMap<>();

    static {
        register("sah", SahBuilder::new);
        register("median-plane", MedianPlaneBuilder::new);
        register("object-median", ObjectMedianBuilder::new);
        register("sliding-midpoint", SlidingMidpointBuilder::new);
        for (ServiceLoader.Provider<KdTreeBuilder> p : ServiceLoader.load(KdTreeBuilder.class).stream().toList())
            register(p.get().name(), () -> newInstance(p.type()));
    }

    /** A new builder of a class found by the service loader (which checked its public no-argument constructor). */
    private static KdTreeBuilder newInstance(Class<? extends KdTreeBuilder> type) {
        try {
            return type.getConstructor().newInstance();
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException("cannot make a " + type.getName() + ": " + e, e);
        }
    }

    private Builders() {
    }

    /**
     * Makes {@code factory}'s builders available under {@code name} (replacing any before).
     *
     * @param name the builder's name, as the command line and workbench know it
     * @param factory makes a new builder with its default settings
     */
    public static synchronized void register(String name, Supplier<? extends KdTreeBuilder> factory) {
        BY_NAME.put(name, factory);
        ROWS.remove(name);
    }

    /**
     * Registers the builders a plug-in jar lists in {@code META-INF/services/org.kdtree.kdtree.KdTreeBuilder},
     * or those of every jar in a plug-in folder: the command line's {@code --plugin}.
     *
     * @param jarOrFolder a jar, or a folder whose {@code .jar} files are loaded
     * @return the names registered
     * @throws IllegalArgumentException if the path is neither, or lists no builder
     */
    public static synchronized List<String> loadPlugins(Path jarOrFolder) {
        List<URL> jars = new ArrayList<>();
        List<Path> jarFiles = jarsOf(jarOrFolder);
        for (Path jar : jarFiles) jars.add(PluginJar.open(jar));
        Map<String, Class<? extends KdTreeBuilder>> found = new LinkedHashMap<>();
        Map<String, Path> from = new LinkedHashMap<>();
        List<String> listed = new ArrayList<>();
        try {
            for (int i = 0; i < jarFiles.size(); i++) {
                // the jar's own classes first (two students' com.example.MyBuilder stay two), the others for what it uses
                List<URL> order = new ArrayList<>(jars);
                order.add(0, order.remove(i));
                URLClassLoader loader = new URLClassLoader(order.toArray(URL[]::new), Builders.class.getClassLoader());
                Set<String> ownClasses = PluginJar.listedClasses(jarFiles.get(i));
                for (ServiceLoader.Provider<KdTreeBuilder> p : ServiceLoader.load(KdTreeBuilder.class, loader).stream().toList()) {
                    if (!ownClasses.contains(p.type().getName())) continue; // another jar's, or the library's seen through the parent
                    String name = p.get().name();
                    Class<? extends KdTreeBuilder> before = found.putIfAbsent(name, p.type());
                    if (before != null && before != p.type())
                        throw new IllegalArgumentException(jarOrFolder + ": two jars register the builder '" + name + "': "
                                + from.get(name) + " and " + jarFiles.get(i) + "; keep one of them, or give one builder another name()");
                    from.putIfAbsent(name, jarFiles.get(i));
                    if (!listed.contains(name)) listed.add(name);
                }
            }
        } catch (java.util.ServiceConfigurationError | LinkageError e) {
            throw new IllegalArgumentException(jarOrFolder + ": " + unloadable(e), e);
        }
        if (listed.isEmpty()) throw new IllegalArgumentException(jarOrFolder + ": " + noBuilder(jarFiles));
        List<String> registered = new ArrayList<>();
        for (var e : found.entrySet()) {
            Class<? extends KdTreeBuilder> type = e.getValue();
            if (type.getClassLoader() == Builders.class.getClassLoader() && BY_NAME.containsKey(e.getKey())) continue; // known already: same class
            register(e.getKey(), () -> newInstance(type));
            registered.add(e.getKey());
        }
        try {
            SettingsTable.all();   // a plug-in's rows must not take another row's option
        } catch (IllegalArgumentException e) {
            registered.forEach(BY_NAME::remove);
            throw new IllegalArgumentException(jarOrFolder + ": " + e.getMessage());
        }
        return listed;
    }

    /**
     * The jar each plug-in builder name came from, for the command line to refuse one name given
     * by two {@code --plugin}s.
     *
     * @param jarOrFolder what {@link #loadPlugins} was given
     * @param names the names it returned
     * @param seen the names loaded before, each with the jar or folder that gave it; updated
     * @throws IllegalArgumentException if one of {@code names} came from another jar or folder before
     */
    public static void requireDistinct(Path jarOrFolder, List<String> names, Map<String, Path> seen) {
        for (String name : names) {
            Path before = seen.putIfAbsent(name, jarOrFolder);
            if (before != null && !before.toAbsolutePath().normalize().equals(jarOrFolder.toAbsolutePath().normalize()))
                throw new IllegalArgumentException("two plug-ins register the builder '" + name + "': " + before + " and "
                        + jarOrFolder + "; keep one of them, or give one builder another name()");
        }
    }

    /** Why a listed builder could not be loaded, from the deepest cause, with what to do. */
    private static String unloadable(Throwable e) {
        Throwable root = e;
        while (root.getCause() != null && root.getCause() != root) root = root.getCause();
        if (root instanceof UnsupportedClassVersionError v)
            return "a builder class was compiled for a newer Java than this one runs (" + v.getMessage()
                    + "); compile it for Java " + Runtime.version().feature() + " (maven.compiler.release, or javac --release)";
        if (root instanceof LinkageError l) return "a builder class cannot be loaded (" + l + ")";
        return "a listed builder cannot be made: " + root;
    }

    /** The plug-in's jars: the file itself (whatever its name: it is checked as a zip), or a folder's .jar files. */
    private static List<Path> jarsOf(Path jarOrFolder) {
        if (Files.isRegularFile(jarOrFolder)) return List.of(jarOrFolder);
        if (!Files.isDirectory(jarOrFolder)) throw new IllegalArgumentException(jarOrFolder + ": no such jar or folder");
        try (var files = Files.list(jarOrFolder)) {
            return files.filter(f -> f.toString().endsWith(".jar")).sorted().toList();
        } catch (IOException e) {
            throw new IllegalArgumentException(jarOrFolder + ": the folder cannot be read (" + e.getMessage() + ")");
        }
    }

    /** Why no builder was found, and what to do: the service file a jar needs, with its line. */
    private static String noBuilder(List<Path> jars) {
        if (jars.isEmpty()) return "no builder listed in " + PluginJar.SERVICES + " (the folder holds no .jar)";
        List<Path> without = jars.stream().filter(j -> !PluginJar.listsBuilders(j)).toList();
        if (without.size() == 1 && jars.size() == 1)
            return "the jar lists no builder; " + PluginJar.missingServices(without.get(0), "the jar");
        if (without.size() == jars.size())
            return "no jar in the folder lists a builder; " + PluginJar.missingServices(jars.get(0), "your builder's jar");
        return "no builder listed in " + PluginJar.SERVICES + " could be loaded";
    }

    /**
     * Forgets a registered builder (a test's plug-in, once the test is done).
     *
     * @param name the builder's name; nothing happens if none has it
     */
    public static synchronized void remove(String name) {
        BY_NAME.remove(name);
        ROWS.remove(name);
    }

    /** {@return the registered names, in registration order} */
    public static synchronized Set<String> names() {
        return java.util.Collections.unmodifiableSet(new java.util.LinkedHashSet<>(BY_NAME.keySet()));
    }

    /**
     * A new builder of that name, with its default settings.
     *
     * @param name a registered name
     * @return the new builder
     * @throws IllegalArgumentException if no builder has that name
     */
    public static synchronized KdTreeBuilder create(String name) {
        Supplier<? extends KdTreeBuilder> f = BY_NAME.get(name);
        if (f == null)
            throw new IllegalArgumentException("unknown builder '" + name + "' (known: " + String.join(", ", BY_NAME.keySet()) + ")");
        return f.get();
    }

    /**
     * {@return the setting rows of the builder registered as {@code name}}, asked of a new builder
     * once and kept until the name is registered again or removed
     *
     * @param name a registered name
     * @throws IllegalArgumentException if no builder has that name
     */
    public static synchronized List<Setting<?>> settingRows(String name) {
        List<Setting<?>> rows = ROWS.get(name);
        if (rows == null) {
            rows = List.copyOf(create(name).settingRows());
            ROWS.put(name, rows);
        }
        return rows;
    }
}
