package org.kdtree.cli;

import java.io.BufferedWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.kdtree.build.Builders;
import org.kdtree.build.KdTreeBuilder;
import org.kdtree.io.PointCsv;
import org.kdtree.points.NearestQuery;
import org.kdtree.points.PointTree;
import org.kdtree.shape.PointsKd;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code knn POINTS.csv --queries QUERIES.csv --k K [--radius R] [--builder NAME] --out RESULT.csv}:
 * the k nearest points of each query, exact. See docs/points.md for the formats.
 */
@Command(name = "knn", mixinStandardHelpOptions = true,
        description = {"The k nearest neighbours of each query point (exact, Euclidean).",
                "Points and queries: CSV, one point per line, coordinates separated by commas;",
                "blank lines and lines starting with # are skipped.",
                "Writes one line per query, in query order: the 0-based indices of its neighbours",
                "in POINTS, nearest first, comma-separated (ties by lower index; empty if none).",
                "Prints one summary line."})
public final class KnnCommand implements Callable<Integer> {
    @Parameters(paramLabel = "POINTS", description = "The points (CSV).")
    Path pointsFile;

    @Option(names = "--queries", required = true, paramLabel = "FILE", description = "The query points (CSV, the points' dimension).")
    Path queriesFile;

    @Option(names = "--k", required = true, paramLabel = "K", description = "Neighbours per query, >= 1 (all points if K exceeds their number).")
    int k;

    @Option(names = "--radius", paramLabel = "R", description = "Keep only neighbours at distance <= R (R >= 0).")
    Double radius;

    @Option(names = {"-b", "--builder"}, defaultValue = "sliding-midpoint", paramLabel = "NAME",
            description = "Builder: sliding-midpoint, median-plane, object-median, sah, or a registered name (default: ${DEFAULT-VALUE}).")
    String builder;

    @Option(names = "--out", required = true, paramLabel = "FILE", description = "Where the neighbour lines go.")
    Path outFile;

    @Override public Integer call() throws Exception {
        if (k < 1) throw new IllegalArgumentException("--k must be >= 1, got " + k);
        if (radius != null && !(radius >= 0 && radius < Double.POSITIVE_INFINITY))
            throw new IllegalArgumentException("--radius must be a finite number >= 0, got " + radius);
        KdTreeBuilder b = Builders.create(builder);
        CommandFiles.requireFolder("--out", outFile);
        PointsKd points = PointCsv.read(pointsFile);
        PointsKd queries = PointCsv.read(queriesFile);
        if (queries.dimension() != points.dimension())
            throw new IllegalArgumentException(queriesFile + ": the queries are " + queries.dimension() + "-D, the points "
                    + points.dimension() + "-D (" + pointsFile + ")");
        long t0 = System.nanoTime();
        PointTree tree = PointTree.build(points, b);
        long t1 = System.nanoTime();
        int kk = Math.min(k, points.size());
        int[] neighbours = new int[queries.size() * kk];
        int[] counts = new int[queries.size()];
        search(tree, queries, kk, neighbours, counts);
        long t2 = System.nanoTime();
        write(neighbours, counts, kk);
        System.out.println(String.format(Locale.ROOT, "knn: %d points, %d queries, %d-D, k %d%s, builder %s, build %.1f ms, query %.1f ms",
                points.size(), queries.size(), points.dimension(), k, radius != null ? ", radius " + radius : "", b.name(),
                (t1 - t0) / 1e6, (t2 - t1) / 1e6));
        return 0;
    }

    /** Every query's neighbours into {@code neighbours[q kk ..]}, their number into {@code counts[q]}. */
    private void search(PointTree tree, PointsKd queries, int kk, int[] neighbours, int[] counts) {
        NearestQuery knn = new NearestQuery(tree);
        int dim = queries.dimension();
        double[] q = new double[dim];
        int[] found = new int[kk];
        double maxDistance = radius != null ? radius : Double.POSITIVE_INFINITY;
        for (int j = 0; j < queries.size(); j++) {
            for (int a = 0; a < dim; a++) q[a] = queries.coord(j, a);
            counts[j] = knn.nearest(q, kk, maxDistance, found, null);
            System.arraycopy(found, 0, neighbours, j * kk, counts[j]);
        }
    }

    private void write(int[] neighbours, int[] counts, int kk) throws java.io.IOException {
        try (BufferedWriter out = Files.newBufferedWriter(outFile, StandardCharsets.UTF_8)) {
            StringBuilder line = new StringBuilder();
            for (int j = 0; j < counts.length; j++) {
                line.setLength(0);
                for (int i = 0; i < counts[j]; i++) {
                    if (i > 0) line.append(',');
                    line.append(neighbours[j * kk + i]);
                }
                out.write(line.append('\n').toString());
            }
        }
    }
}
