package org.kdtree.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.kdtree.generate.Points;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.limits.Limits;
import org.kdtree.points.PointTree;
import org.kdtree.shape.PointsKd;
import org.kdtree.tradeoff.ChartFile;
import org.kdtree.tradeoff.DimensionSweep;
import org.kdtree.tradeoff.NeighbourStudy;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code knn-study}: what approximate nearest neighbours cost in accuracy and buy in speed
 * (recall at k against queries per second), or, with {@code --dimensions}, where the exact
 * kd-tree search stops beating brute force. See docs/points.md, "What accuracy costs".
 */
@Command(name = "knn-study", mixinStandardHelpOptions = true,
        description = {"What accuracy costs for k nearest neighbours: recall against queries per second.",
                "For each best-bin-first budget (leaves scanned) and each epsilon, the recall at k (the fraction of "
                        + "the true k nearest found, against brute force) and the queries per second, "
                        + "with the exact kd-tree search and brute force as references.",
                "Data: POINTS and --queries files (CSV, as for knn), or --generate.",
                "With --dimensions: the exact search against brute force on generated data",
                "at each dimension, where kd-trees stop helping.",
                "One thread; prints a table, writes a CSV and a chart (PNG or SVG)."})
final class KnnStudyCommand implements Callable<Integer> {
    @Parameters(paramLabel = "POINTS", arity = "0..1", description = "The points (CSV); or use --generate.")
    Path pointsFile;

    @Option(names = "--queries", paramLabel = "FILE", description = "The query points (CSV, the points' dimension).")
    Path queriesFile;

    @Option(names = "--k", required = true, paramLabel = "K", description = "Neighbours per query (see docs/limits.md).")
    int k;

    @Mixin
    BuilderOptions options = BuilderOptions.kdTrees("sliding-midpoint", null);

    @Option(names = "--budgets", split = ",", paramLabel = "L", defaultValue = "1,2,4,8,16,32,64,128",
            description = "Best-bin-first budgets: leaves scanned per query (default: ${DEFAULT-VALUE}).")
    List<Integer> budgets;

    @Option(names = "--epsilons", split = ",", paramLabel = "E", description = "Epsilons of the (1 + eps) bound (default: none).")
    List<Double> epsilons;

    @Option(paramLabel = "N", names = "--runs", defaultValue = "3", description = "Timed passes per measurement, after a warm-up; the median is kept (default: ${DEFAULT-VALUE}).")
    int runs;

    @Option(names = "--generate", paramLabel = "KIND", description = "Generate the points and queries instead of reading them: uniform or clustered.")
    String generate;

    @Option(paramLabel = "N", names = "--n", defaultValue = "10000", description = "Generated points (default: ${DEFAULT-VALUE}).")
    int n;

    @Option(paramLabel = "N", names = "--dimension", defaultValue = "3", description = "Generated points' dimension (default: ${DEFAULT-VALUE}).")
    int dimension;

    @Option(paramLabel = "N", names = "--query-count", defaultValue = "1000", description = "Generated query points (default: ${DEFAULT-VALUE}).")
    int queryCount;

    @Option(paramLabel = "N", names = "--seed", defaultValue = "1", description = "Seed of the generated data (default: ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--dimensions", split = ",", paramLabel = "D",
            description = "Sweep: the exact search against brute force on generated data (uniform unless --generate says) at each dimension.")
    List<Integer> dimensions;

    @Mixin
    StudyOutputs outputs = new StudyOutputs("DATA");

    @Mixin
    ProgressOption progress;

    @Override public Integer call() throws Exception {
        checkOptions();
        KdTreeBuilder b = options.spec().create();
        if (dimensions != null) return sweep(b);
        PointsKd points = generate != null ? Points.named(kind(), n, dimension, seed) : CommandFiles.readPoints(pointsFile);
        PointsKd queries = generate != null ? Points.namedQueries(kind(), queryCount, dimension, seed)   // of the points' dimension
                : CommandFiles.readQueries(queriesFile, points, pointsFile);
        Limits.DIMENSION.check("the points' dimension", points.dimension());
        return study(PointTree.build(points, b), queries, b);
    }

    /** Every option against its limit, and the data given one way only, before any work. */
    private void checkOptions() {
        Limits.NEIGHBOURS.check("--k", k);
        Limits.RUNS.check("--runs", runs);
        for (int budget : budgets) Limits.LEAF_BUDGET.check("--budgets", budget);
        if (epsilons != null) for (double e : epsilons) Limits.EPSILON.check("--epsilons", e);
        Limits.POINT_COUNT.check("--n", n);
        Limits.DIMENSION.check("--dimension", dimension);
        Limits.QUERY_COUNT.check("--query-count", queryCount);
        if (dimensions != null) for (int d : dimensions) Limits.DIMENSION.check("--dimensions", d);
        if (generate != null) kind();
        boolean files = pointsFile != null || queriesFile != null;
        if (dimensions != null && files)
            throw new IllegalArgumentException("--dimensions generates its data; give no POINTS or --queries");
        if (dimensions == null && generate != null && files)
            throw new IllegalArgumentException("give POINTS and --queries, or --generate, not both");
        if (dimensions == null && generate == null && (pointsFile == null || queriesFile == null))
            throw new IllegalArgumentException("give POINTS and --queries FILE, or --generate uniform|clustered");
        outputs.check(dataName(), "POINTS", pointsFile, "--queries", queriesFile);
    }

    /** The generated set's name ({@link Points#named}), lower case; uniform unless {@code --generate} says. */
    private String kind() {
        String name = generate == null ? "uniform" : generate.toLowerCase(Locale.ROOT);
        if (!Points.NAMES.contains(name)) throw new IllegalArgumentException("--generate must be uniform or clustered, got '" + generate + "'");
        return name;
    }

    /** The data's name in file names and captions. */
    private String dataName() {
        if (dimensions != null) return kind() + "-dimensions";
        if (generate != null) return kind() + "-" + dimension + "d";
        return pointsFile.getFileName().toString().replaceFirst("\\.[^.]*$", "");
    }

    private Path csvFile() {
        return outputs.csv(dataName());
    }

    private Path chartFile() {
        return outputs.chart(dataName());
    }

    private int study(PointTree tree, PointsKd queries, KdTreeBuilder b) throws Exception {
        System.out.printf(Locale.ROOT, "data: %s, %,d points, %,d queries, %d-D, k %d, builder %s, %d run(s), one thread%n",
                dataName(), tree.size(), queries.size(), tree.dimension(), k, b.name(), runs);
        int steps = 3 + budgets.size() + (epsilons == null ? 0 : epsilons.size());
        List<NeighbourStudy.Result> results = new ArrayList<>();
        StudyFile table = new StudyFile(csvFile());
        try (ProgressBar bar = progress.bar(steps, "steps")) {
            bar.step(0, "exact answers (brute force)");
            NeighbourStudy s = new NeighbourStudy(tree, queries, k, runs);
            bar.print(System.out, String.format(Locale.ROOT, "%-24s %8s %14s %10s %12s", "search", "recall", "queries/s",
                    "speed-up", "leaves/query"));
            measure(bar, 1, "brute force", results, s::bruteForce, table);
            measure(bar, 2, "exact kd-tree", results, s::exact, table);
            for (int i = 0; i < budgets.size(); i++) {
                int budget = budgets.get(i);
                measure(bar, 3 + i, "budget " + budget, results, () -> s.budget(budget), table);
            }
            for (int i = 0; epsilons != null && i < epsilons.size(); i++) {
                double eps = epsilons.get(i);
                measure(bar, 3 + budgets.size() + i, "epsilon " + eps, results, () -> s.epsilon(eps), table);
            }
        }
        table.finish(NeighbourStudy.csv(results));
        String caption = ChartFile.caption(String.format(Locale.ROOT, "%s: %,d points, %d-D, %,d queries, k %d, builder %s; median of %d run%s",
                dataName(), tree.size(), tree.dimension(), queries.size(), k, b.name(), runs, runs == 1 ? "" : "s"), 1);
        NeighbourStudy.writeChart(results, dataName() + ": recall at k = " + k + " against queries per second", caption, chartFile());
        System.out.println("wrote " + csvFile() + " and " + chartFile());
        String warning = tooShortToTime(results, queries.size());
        if (warning != null) System.out.println(warning);
        return 0;
    }

    /** A pass shorter than this is timed mostly as the clock's and the JIT's noise. */
    static final double SHORTEST_PASS_SECONDS = 0.02;

    /**
     * {@return a warning if a timed pass of some search took under {@link #SHORTEST_PASS_SECONDS}}
     * (a small input: its queries per second and speed-ups mislead), or null
     */
    static String tooShortToTime(List<NeighbourStudy.Result> results, int queries) {
        double shortest = Double.POSITIVE_INFINITY;
        for (NeighbourStudy.Result r : results)
            if (r.queriesPerSecond() > 0) shortest = Math.min(shortest, queries / r.queriesPerSecond());
        if (!(shortest < SHORTEST_PASS_SECONDS)) return null;
        return String.format(Locale.ROOT, "warning: a timed pass took only %.2f ms (%,d queries): too short to time well, so the "
                + "queries/s and speed-ups above are mostly noise; give more points or queries (--n, --query-count), at least "
                + "%.0f ms a pass", shortest * 1e3, queries, SHORTEST_PASS_SECONDS * 1e3);
    }

    /** Announces step {@code step} on the bar, measures it, keeps its row, and prints its line above the bar. */
    private static void measure(ProgressBar bar, int step, String name, List<NeighbourStudy.Result> results,
                                java.util.function.Supplier<NeighbourStudy.Result> what, StudyFile table) throws java.io.IOException {
        bar.step(step, name);
        NeighbourStudy.Result r = what.get();
        results.add(r);
        table.progress(NeighbourStudy.csv(results));
        bar.print(System.out, String.format(Locale.ROOT, "%-24s %8.4f %14.0f %10.2f %12.1f", r.name(), r.recall(),
                r.queriesPerSecond(), r.speedUp(), r.leavesPerQuery()));
    }

    private int sweep(KdTreeBuilder b) throws Exception {
        System.out.printf(Locale.ROOT, "data: %s, %,d points, %,d queries, k %d, builder %s, %d run(s), one thread%n",
                kind(), n, queryCount, k, b.name(), runs);
        System.out.printf(Locale.ROOT, "%9s %14s %14s %10s %12s%n", "dimension", "exact q/s", "brute q/s", "speed-up", "leaves/query");
        DimensionSweep sweep = new DimensionSweep(kind(), n, queryCount, k, runs, seed, b);
        List<DimensionSweep.Result> results = new ArrayList<>();
        StudyFile table = new StudyFile(csvFile());
        try (ProgressBar bar = progress.bar(dimensions.size(), "dimensions")) {
            for (int i = 0; i < dimensions.size(); i++) {
                bar.step(i, dimensions.get(i) + "-D");
                DimensionSweep.Result r = sweep.measure(dimensions.get(i));
                results.add(r);
                table.progress(DimensionSweep.csv(results));
                bar.print(System.out, String.format(Locale.ROOT, "%9d %14.0f %14.0f %10.2f %12.1f", r.dimension(),
                        r.exactQps(), r.bruteQps(), r.speedUp(), r.leavesPerQuery()));
            }
        }
        table.finish(DimensionSweep.csv(results));
        String caption = ChartFile.caption(String.format(Locale.ROOT, "%s points: %,d, %,d queries, k %d, builder %s; median of %d run%s",
                kind(), n, queryCount, k, b.name(), runs, runs == 1 ? "" : "s"), 1);
        sweep.writeChart(results, caption, chartFile());
        System.out.println("wrote " + csvFile() + " and " + chartFile());
        return 0;
    }
}
