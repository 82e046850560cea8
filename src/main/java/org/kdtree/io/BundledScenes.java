package org.kdtree.io;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URI;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.file.FileSystem;
import java.nio.file.FileSystemAlreadyExistsException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.Scene2D;

/**
 * The scenes of the repository's {@code scenes/} folder, packaged in the jar as class-path
 * resources, so that every command and the workbench find them from any working directory:
 * {@code scenes:cornell-box}, or the plain name {@code cornell-box} (or {@code cornell-box.json})
 * when no such file exists. A bundled scene is handed out as a {@link Path} (inside the jar, a
 * path of its zip file system), so the readers, and JSON scenes naming OBJ files beside them,
 * read it as they read any file.
 */
public final class BundledScenes {
    /** The prefix that names a bundled scene explicitly. */
    public static final String PREFIX = "scenes:";

    /** The bundled scene files (the folder's top level; {@code meshes/} holds what they name). */
    public static final List<String> FILES = List.of("talk-figures.scene2d", "uniform-200.scene2d", "clustered-200.scene2d",
            "long-thin.scene2d", "overlapping-60.scene2d", "cornell-box.json", "sphereflake.json",
            "diffuse-only.json", "shadows-only.json", "obj-materials.json", "clustered-spheres.obj");

    private BundledScenes() {
    }

    /** {@return the bundled scenes' names, without extension, e.g. "cornell-box"} */
    public static List<String> names() {
        return FILES.stream().map(BundledScenes::stem).toList();
    }

    /**
     * The file a command line or dialog means: the file itself if it exists; else, for
     * {@code scenes:NAME}, {@code NAME} or {@code scenes/NAME}, the bundled scene of that name
     * (with or without extension).
     * @param given what the user typed
     * @return the path to read
     * @throws IllegalArgumentException naming the bundled scenes if {@code scenes:NAME} names none
     */
    public static Path resolve(String given) {
        if (!given.startsWith(PREFIX) && Files.exists(Path.of(given))) return Path.of(given);
        Optional<Path> bundled = find(given.startsWith(PREFIX) ? given.substring(PREFIX.length()) : given);
        if (bundled.isPresent()) return bundled.get();
        if (given.startsWith(PREFIX))
            throw new IllegalArgumentException(given + ": no bundled scene of that name (bundled: " + String.join(", ", names()) + ")");
        return Path.of(given);
    }

    /**
     * The bundled scene of that name.
     * @param name e.g. "cornell-box", "cornell-box.json" or "scenes/cornell-box.json"
     * @return its path, or empty if no bundled scene has that name
     */
    public static Optional<Path> find(String name) {
        String n = name.startsWith("scenes/") ? name.substring("scenes/".length()) : name;
        for (String f : FILES)
            if (f.equals(n) || stem(f).equals(n.toLowerCase(Locale.ROOT))) return Optional.of(path(f));
        return Optional.empty();
    }

    /**
     * The bundled scene of that name, which must exist.
     * @param file one of {@link #FILES}
     * @return its path
     */
    public static Path path(String file) {
        URL url = BundledScenes.class.getResource("/scenes/" + file);
        if (url == null) throw new IllegalStateException("bundled scene " + file + " is missing from the class path");
        try {
            URI uri = url.toURI();
            if ("jar".equals(uri.getScheme())) openZip(uri);
            return Path.of(uri);
        } catch (URISyntaxException e) {
            throw new IllegalStateException(url + ": " + e.getMessage(), e);
        }
    }

    /**
     * Reads a bundled scene, which must exist, by its extension ({@link PrimitivesReader}).
     * @param file one of {@link #FILES}
     * @return its primitives
     * @throws UncheckedIOException if it cannot be read (a broken jar)
     */
    public static Primitives load(String file) {
        try {
            return PrimitivesReader.read(path(file));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Reads a bundled 2-D scene, which must exist: the talk's figures ({@code talk-figures.scene2d}) or one the workbench names.
     * @param file one of the {@code .scene2d} files of {@link #FILES}
     * @return its shapes
     * @throws UncheckedIOException if it cannot be read (a broken jar)
     */
    public static Scene2D read2D(String file) {
        try {
            return Scene2DReader.read(path(file));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Opens the jar's zip file system once, so that {@link Path#of(URI)} can reach inside it. */
    private static synchronized void openZip(URI uri) {
        try {
            FileSystem unused = FileSystems.newFileSystem(uri, Map.of());
        } catch (FileSystemAlreadyExistsException already) {
            // opened before: Path.of finds it
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static String stem(String file) {
        int dot = file.lastIndexOf('.');
        return dot < 0 ? file : file.substring(0, dot);
    }
}
