package org.kdtree.examples;

import java.nio.file.Path;
import org.kdtree.accel.Hit;
import org.kdtree.geom.Ray;
import org.kdtree.io.BundledScenes;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.Quality;
import org.kdtree.kdtree.SahBuilder;
import org.kdtree.kdtree.Traverser;
import org.kdtree.shape.TriangleMesh;

/** Loads a mesh (an OBJ file, a JSON scene, or by default a bundled scene), builds a tree, traces a ray, prints the statistics. */
public final class LibraryExample {
    private LibraryExample() {
    }

    /**
     * Runs the example.
     *
     * @param args an optional OBJ file, JSON scene or bundled 3-D scene (default {@code scenes:clustered-spheres})
     * @throws Exception if the mesh cannot be read
     */
    public static void main(String[] args) throws Exception {
        Path file = BundledScenes.resolve(args.length > 0 ? args[0] : "scenes:clustered-spheres");  // any folder
        TriangleMesh mesh = PrimitivesReader.readMesh(file);                                // .obj or .json: its triangles
        KdTree tree = new SahBuilder().quality(Quality.EXACT).build(mesh);                 // the talk's Kt, Ki, lambda
        Traverser rays = new Traverser(tree);                                              // one per thread
        double[] aim = new double[3];                                                       // triangle 0's centre
        for (int a = 0; a < 3; a++) aim[a] = (mesh.corner(0, 0, a) + mesh.corner(0, 1, a) + mesh.corner(0, 2, a)) / 3;
        Ray ray = new Ray(new double[] {aim[0], aim[1], aim[2] - 100}, new double[] {0, 0, 1});
        Hit hit = new Hit();
        if (rays.closestHit(ray, 0, Double.POSITIVE_INFINITY, hit))
            System.out.println("hit triangle " + hit.primitive + " at t = " + hit.t);
        else
            System.out.println("miss");
        System.out.println(tree.stats().describe());                                     // nodes, depth, expected cost...
    }
}
