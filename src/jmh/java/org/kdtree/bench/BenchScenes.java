package org.kdtree.bench;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import org.kdtree.generate.MeshGrid;
import org.kdtree.generate.Meshes;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.shape.TriangleMesh;

/** Scenes by name for the benchmarks: a generated scene ({@link Meshes#named}: {@code uniform}, {@code clustered}, {@code surface}), or an OBJ path (optionally {@code PATH@grid4}). */
public final class BenchScenes {
    private BenchScenes() {
    }

    public static TriangleMesh make(String kind, int n) {
        return switch (kind) {
            case "uniform", "clustered", "surface" -> Meshes.named(kind, n);
            default -> load(kind);
        };
    }

    public static TriangleMesh load(String spec) {
        try {
            boolean grid = spec.endsWith("@grid4");
            TriangleMesh m = PrimitivesReader.readMesh(Path.of(grid ? spec.substring(0, spec.length() - 6) : spec));
            return grid ? MeshGrid.grid(m, 4) : m;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
