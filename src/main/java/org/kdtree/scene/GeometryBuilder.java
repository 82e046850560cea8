package org.kdtree.scene;

import java.util.Arrays;
import org.joml.Matrix3d;
import org.joml.Matrix4d;
import org.joml.Vector3d;
import org.kdtree.shape.TriangleMesh;

/**
 * Collects the scene's triangles into flat arrays, applying the current object's transform to
 * every vertex (and its inverse transpose to normals). The transform is built step by step
 * ({@link #translate}, {@link #scale}, {@link #rotate}, each applied after the ones before);
 * JOML's matrices hold it, inside this class only.
 */
public final class GeometryBuilder {
    private double[] vertices = new double[3 * 1024];
    private double[] normals = new double[3 * 1024];
    private int vertexCount;
    private int[] indices = new int[3 * 1024];
    private int[] materials = new int[1024];
    private boolean[] smooth = new boolean[1024];
    private int triangleCount;
    private final Matrix4d transform = new Matrix4d();
    private final Matrix4d step = new Matrix4d();
    private final Matrix3d normalTransform = new Matrix3d();
    private final Vector3d tmp = new Vector3d();

    /**
     * Applies no transform to the vertices added from now on (as at the start): a new object.
     *
     * @return this builder
     */
    public GeometryBuilder resetTransform() {
        transform.identity();
        transform.normal(normalTransform);
        return this;
    }

    /**
     * Moves the vertices added from now on by {@code by}, after the steps so far.
     *
     * @param by the translation
     * @return this builder
     */
    public GeometryBuilder translate(Vec3 by) {
        return then(step.translation(by.x(), by.y(), by.z()));
    }

    /**
     * Scales the vertices added from now on by {@code factors} per axis, after the steps so far.
     *
     * @param factors the scale on x, y and z (none zero)
     * @return this builder
     */
    public GeometryBuilder scale(Vec3 factors) {
        return then(step.scaling(factors.x(), factors.y(), factors.z()));
    }

    /**
     * Rotates the vertices added from now on about {@code unitAxis} through the origin, after the steps so far.
     *
     * @param degrees  the angle, counter-clockwise looking down the axis
     * @param unitAxis the axis, of length 1
     * @return this builder
     */
    public GeometryBuilder rotate(double degrees, Vec3 unitAxis) {
        return then(step.rotation(Math.toRadians(degrees), unitAxis.x(), unitAxis.y(), unitAxis.z()));
    }

    /** The transform so far, then {@code s} (s times it: later steps apply after earlier ones). */
    private GeometryBuilder then(Matrix4d s) {
        transform.set(s.mul(transform));
        transform.normal(normalTransform);
        return this;
    }

    /** {@return the number of vertices added so far} */
    public int vertexCount() { return vertexCount; }
    /** {@return the number of triangles added so far} */
    public int triangleCount() { return triangleCount; }

    /**
     * Adds a vertex (transformed) with a normal (zero for none); returns its index.
     *
     * @param p the position, before the transform
     * @param n the normal, before the transform, or zero for none
     * @return the vertex's index
     */
    public int vertex(Vec3 p, Vec3 n) {
        int i = 3 * vertex(p.x(), p.y(), p.z());
        normalTransform.transform(tmp.set(n.x(), n.y(), n.z()));
        if (tmp.lengthSquared() > 0) tmp.normalize();
        normals[i] = tmp.x; normals[i + 1] = tmp.y; normals[i + 2] = tmp.z;
        return i / 3;
    }

    /**
     * Adds a vertex (transformed) without a normal, as a file's meshes give them; returns its index.
     *
     * @param x the first coordinate, before the transform
     * @param y the second coordinate, before the transform
     * @param z the third coordinate, before the transform
     * @return the vertex's index
     */
    public int vertex(double x, double y, double z) {
        if (3 * vertexCount + 3 > vertices.length) {
            vertices = Arrays.copyOf(vertices, vertices.length * 2);
            normals = Arrays.copyOf(normals, normals.length * 2);
        }
        transform.transformPosition(tmp.set(x, y, z));
        int i = 3 * vertexCount;
        vertices[i] = tmp.x; vertices[i + 1] = tmp.y; vertices[i + 2] = tmp.z;
        normals[i] = 0; normals[i + 1] = 0; normals[i + 2] = 0;
        return vertexCount++;
    }

    /**
     * Adds triangle (a, b, c) of already added vertices.
     *
     * @param a the first vertex's index
     * @param b the second vertex's index
     * @param c the third vertex's index
     * @param material the material index
     * @param smoothShaded whether to interpolate the vertex normals
     */
    public void triangle(int a, int b, int c, int material, boolean smoothShaded) {
        if (3 * triangleCount + 3 > indices.length) {
            indices = Arrays.copyOf(indices, indices.length * 2);
            materials = Arrays.copyOf(materials, materials.length * 2);
            smooth = Arrays.copyOf(smooth, smooth.length * 2);
        }
        indices[3 * triangleCount] = a;
        indices[3 * triangleCount + 1] = b;
        indices[3 * triangleCount + 2] = c;
        materials[triangleCount] = material;
        smooth[triangleCount] = smoothShaded;
        triangleCount++;
    }

    /**
     * {@return the material index of triangle {@code t}, added so far}
     *
     * @param t the triangle's index
     */
    public int materialOf(int t) { return materials[t]; }

    /**
     * Sets the material of triangle {@code t} (a file's triangles are resolved after its materials are read).
     *
     * @param t the triangle's index
     * @param material the material index
     */
    public void material(int t, int material) { materials[t] = material; }

    /**
     * Adds a flat quad a-b-c-d (counter-clockwise seen from the front).
     *
     * @param a the first corner
     * @param b the second corner
     * @param c the third corner
     * @param d the fourth corner
     * @param material the material index
     */
    public void quad(Vec3 a, Vec3 b, Vec3 c, Vec3 d, int material) {
        int i = vertex(a, Vec3.ZERO), j = vertex(b, Vec3.ZERO), k = vertex(c, Vec3.ZERO), l = vertex(d, Vec3.ZERO);
        triangle(i, j, k, material, false);
        triangle(i, k, l, material, false);
    }

    /** {@return the collected geometry} */
    public SceneGeometry finish() {
        TriangleMesh mesh = new TriangleMesh(Arrays.copyOf(vertices, 3 * vertexCount),
                Arrays.copyOf(indices, 3 * triangleCount));
        return new SceneGeometry(mesh, Arrays.copyOf(materials, triangleCount),
                Arrays.copyOf(normals, 3 * vertexCount), Arrays.copyOf(smooth, triangleCount));
    }

    /**
     * A UV sphere with {@code segments} slices around and {@code rings} stacks from pole to pole,
     * smoothly shaded: {@code 2 * segments * (rings - 1)} triangles.
     * @param center the centre
     * @param radius the radius
     * @param segments slices around
     * @param rings stacks from pole to pole
     * @param material the material index
     * @return this builder
     */
    public GeometryBuilder sphere(Vec3 center, double radius, int segments, int rings, int material) {
        Tessellation.sphere(this, center, radius, segments, rings, material);
        return this;
    }

    /**
     * An axis-aligned box from {@code min} to {@code max}, twelve flat triangles facing outward.
     *
     * @param min the lower corner
     * @param max the upper corner
     * @param material the material index
     * @return this builder
     */
    public GeometryBuilder box(Vec3 min, Vec3 max, int material) {
        Tessellation.box(this, min, max, material);
        return this;
    }

    /**
     * A width x height rectangle centred at {@code center}, facing {@code normal}: two triangles.
     *
     * @param center the centre
     * @param normal the side it faces
     * @param width the extent along its first in-plane axis
     * @param height the extent along its second in-plane axis
     * @param material the material index
     * @return this builder
     */
    public GeometryBuilder plane(Vec3 center, Vec3 normal, double width, double height, int material) {
        Tessellation.plane(this, center, normal, width, height, material);
        return this;
    }

    /**
     * Haines' sphereflake: a sphere with nine spheres of a third its radius touching it, each
     * with nine of its own, {@code levels} deep: {@code (9^(levels+1) - 1) / 8} spheres.
     * @param center the centre sphere's centre
     * @param radius the centre sphere's radius
     * @param levels how many generations of child spheres
     * @param segments slices around each sphere
     * @param rings stacks from pole to pole of each sphere
     * @param material the material index
     * @return this builder
     */
    public GeometryBuilder sphereflake(Vec3 center, double radius, int levels, int segments, int rings, int material) {
        Tessellation.sphereflake(this, center, radius, levels, segments, rings, material);
        return this;
    }
}
