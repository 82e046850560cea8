package org.kdtree.bench;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import org.kdtree.io.ObjMeshReader;
import org.kdtree.shape.ProceduralScenes;
import org.kdtree.shape.TriangleMesh;

/** Scenes by name for the benchmarks: {@code uniform}, {@code clustered}, {@code surface}, or an OBJ path (optionally {@code PATH@grid4}). */
public final class BenchScenes {
    private BenchScenes() {
    }

    public static TriangleMesh make(String kind, int n) {
        return switch (kind) {
            case "uniform" -> ProceduralScenes.uniform(n, 1);
            case "clustered" -> ProceduralScenes.clustered(n, 2);
            case "surface" -> ProceduralScenes.surface(n, 3);
            default -> load(kind);
        };
    }

    public static TriangleMesh load(String spec) {
        try {
            boolean grid = spec.endsWith("@grid4");
            TriangleMesh m = ObjMeshReader.read(Path.of(grid ? spec.substring(0, spec.length() - 6) : spec));
            return grid ? ProceduralScenes.grid(m, 4) : m;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
