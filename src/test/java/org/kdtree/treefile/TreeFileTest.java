package org.kdtree.treefile;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.Hit;
import org.kdtree.accel.RayQuery;
import org.kdtree.accel.SharedSettings;
import org.kdtree.generate.Meshes;
import org.kdtree.generate.Points;
import org.kdtree.generate.Shapes;
import org.kdtree.geom.Ray;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.SahBuilder;
import org.kdtree.measure.RayBatch;
import org.kdtree.measure.RaySet;
import org.kdtree.points.NearestQuery;
import org.kdtree.points.PointTree;
import org.kdtree.shape.PointsKd;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.Scene2D;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.spec.BuilderSpec;

/**
 * Issue 43, item 2: a loaded tree answers exactly what the built one answers, for every builder
 * and the BVH, over triangles, 2-D shapes and 5-D points: the same statistics and expected cost,
 * the same hits to the bit, the same checksums on the benchmark's two ray sets, the same
 * neighbours as brute force; and the file names the builder and settings it was built with.
 */
class TreeFileTest {
    private static final TriangleMesh MESH = Meshes.clustered(3000, 43);

    /** Every builder by name, and the BVH with its compact width and the SAH with settings off their defaults. */
    private static List<BuilderSpec> specs() {
        List<BuilderSpec> all = new java.util.ArrayList<>(BuilderSpec.names().stream().map(BuilderSpec::of).toList());
        all.add(BuilderSpec.of("bvh").with(org.kdtree.bvh.BvhBuilder.WIDTH, 2));
        all.add(BuilderSpec.of("sah").with(org.kdtree.kdtree.SahSettings.LAMBDA, 0.5).with(org.kdtree.kdtree.SahSettings.ALGORITHM, SahBuilder.Algorithm.BINNED)
                .with(org.kdtree.kdtree.KdTreeBuilder.PERFECT_SPLITS, false));
        return all;
    }

    @Test void aLoadedTreeHasTheBuiltOnesStatisticsHitsAndChecksums() throws Exception {
        RaySet p = RaySet.primary(MESH, 48), r = RaySet.random(MESH, 20_000);
        for (BuilderSpec spec : specs()) {
            AccelerationStructure built = spec.build(MESH, null);
            SavedTree saved = Saved.read(Saved.bytes(built, spec, MESH), MESH);
            AccelerationStructure loaded = saved.structure();
            assertThat(loaded.stats()).as(spec + " statistics").isEqualTo(built.stats());
            assertThat(loaded.stats().expectedCost()).as(spec + " expected cost").isEqualTo(built.stats().expectedCost());
            assertThat(saved.stats()).as(spec + " the statistics the file states").isEqualTo(built.stats());
            if (loaded instanceof KdTree kd)   // a kd-tree's expected cost is taken as stated: count it again from the loaded voxels
                assertThat(KdTree.restore(MESH, kd.bounds(), kd.costModel(), kd.builderName(), kd.nodeArray(), kd.refArray(),
                        kd.budgetLeaves(), null).stats()).as(spec + " statistics counted again").isEqualTo(built.stats());
            assertThat(loaded.kind()).isEqualTo(built.kind());
            assertThat(loaded.costModel()).isEqualTo(built.costModel());
            assertThat(saved.spec()).as("the builder and settings it was built with").isEqualTo(spec);
            assertThat(saved.settings()).isEqualTo(spec.describe());
            sameHits(spec.toString(), built, loaded, r);
            try (RayBatch a = new RayBatch(1, built::query); RayBatch b = new RayBatch(1, loaded::query)) {
                assertThat(b.trace(p)).as(spec + " set P").isEqualTo(a.trace(p));
                assertThat(b.trace(r)).as(spec + " set R").isEqualTo(a.trace(r));
            }
        }
    }

    /** Closest and any hit, fast and listening queries, ray by ray: the same primitive at the same t, to the bit. */
    private static void sameHits(String what, AccelerationStructure built, AccelerationStructure loaded, RaySet set) {
        double[] rays = set.rays();
        Ray ray = new Ray(3);
        RayQuery[] a = {built.query(), built.query(org.kdtree.accel.TraversalListener.NONE)};
        RayQuery[] b = {loaded.query(), loaded.query(org.kdtree.accel.TraversalListener.NONE)};
        Hit x = new Hit(), y = new Hit();
        int hits = 0;
        for (int i = 0; i < set.size(); i++) {
            ray.set(rays[6 * i], rays[6 * i + 1], rays[6 * i + 2], rays[6 * i + 3], rays[6 * i + 4], rays[6 * i + 5]);
            for (int q = 0; q < 2; q++) {
                boolean hx = a[q].closestHit(ray, 0, Double.POSITIVE_INFINITY, x), hy = b[q].closestHit(ray, 0, Double.POSITIVE_INFINITY, y);
                assertThat(hy).as(what + " ray " + i).isEqualTo(hx);
                if (hx) {
                    hits++;
                    assertThat(y.primitive).as(what + " ray " + i).isEqualTo(x.primitive);
                    assertThat(Double.doubleToLongBits(y.t)).as(what + " ray " + i).isEqualTo(Double.doubleToLongBits(x.t));
                }
                assertThat(b[q].anyHit(ray, 0, 1)).isEqualTo(a[q].anyHit(ray, 0, 1));
            }
        }
        assertThat(hits).as(what + ": rays that hit, twice each").isGreaterThan(set.size() / 10);
    }

    @Test void twoDimensionalShapesLoadWithTheirStatisticsAndHits() throws Exception {
        Scene2D scene = Shapes.mixed(400, 7);
        for (BuilderSpec spec : specs()) {
            AccelerationStructure built = spec.build(scene, null), loaded = Saved.roundTrip(spec, scene);
            assertThat(loaded.stats()).as(spec.toString()).isEqualTo(built.stats());
            Ray ray = new Ray(2);
            Hit x = new Hit(), y = new Hit();
            java.util.Random rnd = new java.util.Random(3);
            RayQuery qa = built.query(), qb = loaded.query();
            for (int i = 0; i < 2000; i++) {
                ray.set(rnd.nextDouble() * 1.2 - 0.1, rnd.nextDouble() * 1.2 - 0.1, rnd.nextGaussian(), rnd.nextGaussian());
                boolean hx = qa.closestHit(ray, 0, Double.POSITIVE_INFINITY, x);
                assertThat(qb.closestHit(ray, 0, Double.POSITIVE_INFINITY, y)).isEqualTo(hx);
                if (hx) assertThat(y.primitive).isEqualTo(x.primitive);
            }
        }
    }

    /** The k nearest neighbours through a loaded 5-D point tree are brute force's (ties by lower index), for every kd-tree builder. */
    @Test void theNeighboursOfALoaded5DPointTreeAreBruteForces() throws Exception {
        PointsKd points = Points.clustered(4000, 5, 11), queries = Points.clusteredQueries(200, 5, 12);
        for (String name : org.kdtree.spec.Builders.names()) {
            BuilderSpec spec = BuilderSpec.of(name);
            KdTree tree = (KdTree) Saved.roundTrip(spec, points);
            NearestQuery knn = new NearestQuery(new PointTree(points, tree));
            int k = 7;
            int[] found = new int[k];
            double[] q = new double[5];
            for (int j = 0; j < queries.size(); j++) {
                for (int a = 0; a < 5; a++) q[a] = queries.coord(j, a);
                int n = knn.nearest(q, k, found, null);
                assertThat(Arrays.copyOf(found, n)).as(name + " query " + j).containsExactly(bruteNearest(points, q, k));
            }
        }
    }

    private static int[] bruteNearest(PointsKd points, double[] q, int k) {
        Integer[] order = new Integer[points.size()];
        double[] d = new double[points.size()];
        for (int i = 0; i < order.length; i++) {
            order[i] = i;
            for (int a = 0; a < q.length; a++) d[i] += (points.coord(i, a) - q[a]) * (points.coord(i, a) - q[a]);
        }
        Arrays.sort(order, (x, y) -> d[x] != d[y] ? Double.compare(d[x], d[y]) : Integer.compare(x, y));
        return Arrays.stream(order).limit(k).mapToInt(Integer::intValue).toArray();
    }

    @Test void aFileSavedAtomicallyIsLoadedByMappingIt(@TempDir Path dir) throws Exception {
        BuilderSpec spec = BuilderSpec.of("sah");
        AccelerationStructure built = spec.build(MESH, null);
        Path file = dir.resolve("clustered" + TreeFile.EXTENSION);
        TreeFile.save(file, built, spec, MESH);
        assertThat(Files.readAllBytes(file)).isEqualTo(Saved.bytes(built, spec, MESH));
        assertThat(TreeFile.isTreeFile(file)).isTrue();
        assertThat(TreeFile.load(file, MESH).structure().stats()).isEqualTo(built.stats());
        try (var files = Files.list(dir)) {
            assertThat(files.toList()).as("no temporary left beside it").containsExactly(file);
        }
    }

    @Test void aTreeLoadedOverOtherPrimitivesIsRefusedNamingTheMismatch() throws Exception {
        BuilderSpec spec = BuilderSpec.of("sah");
        byte[] file = Saved.bytes(spec.build(MESH, null), spec, MESH);
        assertRefused(file, Meshes.clustered(2999, 43), "the tree was built over 3,000 triangles (3-D), the scene has 2,999 triangles (3-D)");
        assertRefused(file, Meshes.clustered(3000, 44), "the tree was built over other 3,000 triangles (3-D): the same count, but their coordinates differ");
        assertRefused(file, Points.uniform(3000, 3, 1), "the scene has 3,000 points (3-D)");
        TriangleMesh moved = org.kdtree.generate.HardMeshes.scaled(MESH, 1 + 1e-15);
        assertRefused(file, moved, "their coordinates differ");
        Primitives shapes = Shapes.mixed(50, 1);
        byte[] file2d = Saved.bytes(spec.build(shapes, null), spec, shapes);
        assertRefused(file2d, Shapes.mixed(50, 2), "other 50 2-D shapes (2-D)");
    }

    static void assertRefused(byte[] file, Primitives primitives, String part) {
        org.assertj.core.api.Assertions.assertThatThrownBy(() -> Saved.read(file, primitives)).isInstanceOf(TreeFileException.class)
                .hasMessageStartingWith("test.kdtree: ").hasMessageContaining(part).message().doesNotContain("\n");
    }
}
