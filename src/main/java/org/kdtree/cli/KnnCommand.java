package org.kdtree.cli;

import java.io.Writer;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.kdtree.files.AtomicFile;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.spec.Structures;
import org.kdtree.limits.Limits;
import org.kdtree.points.NearestQuery;
import org.kdtree.points.PointTree;
import org.kdtree.shape.PointsKd;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code knn POINTS.csv --queries QUERIES.csv --k K [--radius R] [--builder NAME and its settings] --out RESULT.csv}:
 * the k nearest points of each query, exact. See docs/points.md for the formats.
 */
@Command(name = "knn", mixinStandardHelpOptions = true,
        description = {"The k nearest neighbours of each query point (exact, Euclidean).",
                "Points and queries: CSV, one point per line, comma-separated coordinates;",
                "blank lines and lines starting with # are skipped.",
                "Writes one line per query, in query order: the 0-based indices of its",
                "neighbours in POINTS, nearest first, comma-separated (ties by lower index;",
                "an empty line if none).",
                "Prints one summary line."})
final class KnnCommand implements Callable<Integer> {
    @Parameters(paramLabel = "POINTS", description = "The points (CSV).")
    Path pointsFile;

    @Option(names = "--queries", required = true, paramLabel = "FILE", description = "The query points (CSV, the points' dimension).")
    Path queriesFile;

    @Option(names = "--k", required = true, paramLabel = "K", description = "Neighbours per query, >= 1 (all points if K exceeds their number).")
    int k;

    @Option(names = "--radius", paramLabel = "R", description = "Keep only neighbours at distance <= R (R >= 0).")
    Double radius;

    @Mixin
    BuilderOptions options = BuilderOptions.kdTrees("sliding-midpoint", null);

    /** Taken as every command takes it (knn draws no bar: it prints one summary line). */
    @Mixin
    ProgressOption progress;

    @Mixin
    TreeOptions trees = new TreeOptions();

    @Option(names = "--out", required = true, paramLabel = "FILE", description = "Where the neighbour lines go.")
    Path outFile;

    @Override public Integer call() throws Exception {
        Limits.NEIGHBOURS.check("--k", k);
        if (radius != null && !(radius >= 0 && radius < Double.POSITIVE_INFINITY))
            throw new IllegalArgumentException("--radius must be a finite number >= 0, got " + radius);
        KdTreeBuilder b = trees.loads() ? null : options.spec().create();
        trees.check("POINTS", pointsFile, "--queries", queriesFile, "--out", outFile);
        CommandFiles.requireWritable("--out", outFile);
        CommandFiles.requireNotInput("--out", outFile, "POINTS", pointsFile);
        CommandFiles.requireNotInput("--out", outFile, "--queries", queriesFile);
        PointsKd points = CommandFiles.readPoints(pointsFile), queries = CommandFiles.readQueries(queriesFile, points, pointsFile);
        long t0 = System.nanoTime();
        TreeOptions.Obtained made = trees.obtain(options, points, () -> PointTree.build(points, b).tree());
        KdTree kd = Structures.match(made.structure(), t -> t, h -> {
            throw new IllegalArgumentException("--tree " + trees.tree + " holds a bounding volume hierarchy, which answers ray queries "
                    + "only; knn needs a kd-tree");
        });
        PointTree tree = new PointTree(points, kd);
        long buildNanos = System.nanoTime() - t0;
        trees.save(kd, made.spec(), points);
        long queryNanos = answer(tree, queries, Math.min(k, points.size()));
        System.out.println(String.format(Locale.ROOT, "knn: %d points, %d queries, %d-D, k %d%s, builder %s, %s %.1f ms, query %.1f ms",
                points.size(), queries.size(), points.dimension(), k, radius != null ? ", radius " + radius : "", made.spec().builder(),
                trees.loads() ? "load" : "build", buildNanos / 1e6, queryNanos / 1e6));
        return 0;
    }

    /**
     * Answers the queries a block at a time, timing the searches only (not the writing), and
     * writes one line per query, the whole file or nothing; returns the nanoseconds spent searching.
     */
    private long answer(PointTree tree, PointsKd queries, int kk) throws java.io.IOException {
        long[] nanos = new long[1];
        AtomicFile.writeText(outFile, out -> nanos[0] = answer(tree, queries, kk, out));
        return nanos[0];
    }

    /** The searches and the lines of {@link #answer(PointTree, PointsKd, int)}, into {@code out}. */
    private long answer(PointTree tree, PointsKd queries, int kk, Writer out) throws java.io.IOException {
        NearestQuery knn = new NearestQuery(tree);
        int dim = queries.dimension(), block = Math.max(1, Math.min(queries.size(), (1 << 20) / Math.max(1, kk)));
        double[] q = new double[dim];
        int[] found = new int[kk], neighbours = new int[block * kk], counts = new int[block];
        double maxDistance = radius != null ? radius : Double.POSITIVE_INFINITY;
        long nanos = 0;
        StringBuilder line = new StringBuilder();
        for (int from = 0; from < queries.size(); from += block) {
            int to = Math.min(queries.size(), from + block);
            long t0 = System.nanoTime();
            for (int j = from; j < to; j++) {
                for (int a = 0; a < dim; a++) q[a] = queries.coord(j, a);
                counts[j - from] = knn.nearest(q, kk, maxDistance, found, null);
                System.arraycopy(found, 0, neighbours, (j - from) * kk, counts[j - from]);
            }
            nanos += System.nanoTime() - t0;
            for (int j = 0; j < to - from; j++) {
                line.setLength(0);
                for (int i = 0; i < counts[j]; i++) line.append(i > 0 ? "," : "").append(neighbours[j * kk + i]);
                out.write(line.append('\n').toString());
            }
        }
        return nanos;
    }
}
