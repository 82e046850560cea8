package org.kdtree.cli;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.PrintWriter;
import org.kdtree.accel.TriangleIntersector;
import org.kdtree.kdtree.Traverser;
import org.kdtree.shape.TriangleMesh;

/** The ray-file reader, for tests outside the command-line package (the fuzz test). */
public final class RayFileAccess {
    private static final TriangleMesh MESH = new TriangleMesh(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 1, 2});

    private RayFileAccess() {
    }

    /** Traces the rays of {@code in} through a one-triangle scene. */
    public static long trace(BufferedReader in, String name, PrintWriter out) throws IOException {
        TriangleIntersector tris = new TriangleIntersector(MESH);
        return RayFile.trace(in, name, new Traverser(new org.kdtree.kdtree.SahBuilder().build(MESH)), out);
    }
}
