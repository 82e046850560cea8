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
        double[] centre = new double[3], e1 = new double[3], e2 = new double[3];           // triangle 0: its centre, two edges
        for (int a = 0; a < 3; a++) {
            centre[a] = (mesh.corner(0, 0, a) + mesh.corner(0, 1, a) + mesh.corner(0, 2, a)) / 3;
            e1[a] = mesh.corner(0, 1, a) - mesh.corner(0, 0, a);
            e2[a] = mesh.corner(0, 2, a) - mesh.corner(0, 0, a);
        }
        double[] normal = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        double[] origin = new double[3];
        for (int a = 0; a < 3; a++) origin[a] = centre[a] + 1e-3 * normal[a];             // just off its face
        Ray ray = new Ray(origin, new double[] {-normal[0], -normal[1], -normal[2]});     // aimed straight at it
        Hit hit = new Hit();
        if (rays.closestHit(ray, 0, Double.POSITIVE_INFINITY, hit))
            System.out.println("hit triangle " + hit.primitive + " at t = " + hit.t);
        else
            System.out.println("miss");
        System.out.println(tree.stats().describe());                                     // nodes, depth, expected cost...
    }
}
