package org.kdtree.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.kdtree.accel.SharedSettings;
import org.kdtree.kdtree.BuilderFault;
import org.kdtree.limits.Limits;
import org.kdtree.measure.RaySet;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.tradeoff.ChartFile;
import org.kdtree.tradeoff.Tradeoff;
import org.kdtree.tradeoff.Variant;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code tradeoff MESH}: every builder variant's (kd-trees' and BVHs') build time, tree quality and trace speed, with CSV and chart. */
@Command(name = "tradeoff", mixinStandardHelpOptions = true,
        description = {"What accuracy costs in time: every builder variant measured on one mesh.",
                "Builds MESH (.obj) with every builder variant (median plane, "
                + "object median, SAH with lambda 1.0, 0.8 and 0.5, exact vs binned with 8, 32 and 256 bins, perfect splits on/off, "
                + "depth caps, then every other registered builder, then the bounding volume hierarchy with 4, 2 and 8 children per node, "
                + "8 bins and leaves of one triangle), traces a ray workload, and reports build time, expected SAH cost, nodes, memory, "
                + "nodes visited, triangle and box tests per ray, rays per second and the total time for 1, 10 and 100 rays per "
                + "triangle. Writes CSV and a chart (PNG, or SVG if its name ends in .svg) with the Pareto front of build time against trace time."})
final class TradeoffCommand implements Callable<Integer> {
    @Parameters(paramLabel = "MESH", description = "An OBJ mesh, or the bundled one: scenes:clustered-spheres.")
    Path mesh;

    @Mixin
    GridOption grid = new GridOption("Repeat the mesh in a G x G grid (4: the spec's scaling scene).");

    @Option(paramLabel = "P|R", names = "--rays", defaultValue = "R", description = "Ray workload: P (primary, spec), R (random, spec) (default: ${DEFAULT-VALUE}).")
    String rays;

    @Option(paramLabel = "N", names = "--ray-count", defaultValue = "1000000",
            description = "Rays in the workload: R draws this many, P uses a square image of about this many (default: ${DEFAULT-VALUE}).")
    int rayCount;

    @Option(paramLabel = "N", names = "--counted-rays", defaultValue = "100000", description = "Rays traced again to count nodes and tests (default: ${DEFAULT-VALUE}).")
    int countedRays;

    @Option(paramLabel = "N", names = "--runs", defaultValue = "3", description = "Timed runs per variant, after one warm-up; the median is kept (default: ${DEFAULT-VALUE}).")
    int runs;

    @Mixin
    BuilderOptions options = new BuilderOptions(null, "with the settings given, one more variant; "
            + "the settings given apply to every variant that takes them and does not set them itself");

    @Option(names = "--quick", description = "Only median-plane, exact SAH, binned B = 8, 32 and the bvh.")
    boolean quick;

    @Option(paramLabel = "NAME,...", names = "--variants", split = ",", description = "Only these variants (names as listed by the full run).")
    List<String> only;

    @Mixin
    StudyOutputs outputs = new StudyOutputs("MESHNAME");

    @Option(paramLabel = "X", names = "--chart-rpt", defaultValue = "10", description = "Rays per triangle for the chart's trace time (default: ${DEFAULT-VALUE}).")
    double chartRaysPerTriangle;

    @Mixin
    ProgressOption progress;

    @Mixin
    DeadlineOptions deadlines;

    /**
     * The variants to measure: all, the quick ones or those named, plus the one given by {@code -b}
     * (named by its options), each over the settings given.
     */
    private List<Variant> variants() {
        List<Variant> known = new ArrayList<>(Variant.all()), chosen = new ArrayList<>(quick ? Variant.quick() : known);
        if (options.builder() != null) {
            Variant given = new Variant(options.spec().toString().replace(" --", " ").replace(' ', '-'), options.spec());
            known.add(given);
            chosen.add(given);
        }
        if (only != null) {   // every name given must be a variant: a typo is not left out without a word
            List<String> names = known.stream().map(Variant::name).toList();
            List<String> unknown = only.stream().filter(n -> !names.contains(n)).toList();
            if (!unknown.isEmpty())
                throw new IllegalArgumentException("--variants: no variant named " + String.join(", ", unknown) + "; known: " + String.join(", ", names));
            chosen = known.stream().filter(v -> only.contains(v.name())).toList();
        }
        return chosen.stream().map(v -> new Variant(v.name(), v.spec().over(options.spec(v.spec().builder())))).toList();
    }

    @Override public Integer call() throws Exception {
        grid.check();
        Limits.RAY_COUNT.check("--ray-count", rayCount);
        Limits.RAY_COUNT.check("--counted-rays", countedRays);
        Limits.RUNS.check("--runs", runs);
        Limits.RAYS_PER_TRIANGLE.check("--chart-rpt", chartRaysPerTriangle);
        String base = CommandFiles.meshFile(mesh).getFileName().toString().replaceFirst("\\.[^.]*$", "") + grid.suffix();
        outputs.check(base, "MESH", CommandFiles.meshFile(mesh));
        Path csvOut = outputs.csv(base), pngOut = outputs.chart(base);
        List<Variant> variants = variants();   // a name mistyped, or a setting no variant takes: before the mesh is read
        TriangleMesh m = grid.of(CommandFiles.readMesh(mesh, "tradeoff"));
        RaySet set = switch (rays.toUpperCase(Locale.ROOT)) {
            case "P" -> RaySet.primary(m, Math.max(1, (int) Math.round(Math.sqrt(rayCount))));
            case "R" -> RaySet.random(m, rayCount);
            default -> throw new IllegalArgumentException("--rays must be P or R, got " + rays);
        };
        int threads = options.value(SharedSettings.THREADS);   // checked with the variants' specs
        StudyFile table = new StudyFile(csvOut);

        System.out.printf(Locale.ROOT, "scene: %s (%d triangles), rays: %s x %d, %d run(s), %d build thread(s)%n",
                base, m.size(), set.name(), set.size(), runs, threads);
        System.out.printf(Locale.ROOT, "%-22s %10s %10s %9s %8s %8s %8s %9s %11s %11s %11s%n", "variant", "build ms", "SAH cost",
                "nodes", "nodes/r", "tests/r", "boxes/r", "Mrays/s", "1 r/tri ms", "10 r/tri", "100 r/tri");
        Tradeoff t = new Tradeoff(m, set, runs, threads, countedRays).supervisedBy(deadlines.supervisor());
        List<String> skipped = new ArrayList<>();
        List<Tradeoff.Result> results = measureAll(t, variants, table, csvOut, skipped);
        table.finish(Tradeoff.csv(results));
        String caption = ChartFile.caption(String.format(Locale.ROOT, "%s, %,d triangles; %s rays x %,d; median of %d run%s",
                base, m.size(), set.name(), set.size(), runs, runs == 1 ? "" : "s"), threads);
        Tradeoff.writeChart(results, base + ": build time vs trace time (" + set.name() + " rays)", chartRaysPerTriangle,
                caption, pngOut);
        results.stream().map(Tradeoff.Result::engine).distinct().forEach(e -> System.out.println("traced by " + e));
        System.out.println("wrote " + csvOut + " and " + pngOut);
        if (!skipped.isEmpty())
            System.out.println("skipped " + skipped.size() + " variant" + (skipped.size() == 1 ? "" : "s") + " whose builder failed (not in the CSV "
                    + "or the chart): " + String.join(", ", skipped));
        return 0;
    }

    /**
     * Measures each variant, writing the rows so far to the partial file after each; a variant
     * whose builder is at fault (a plug-in's: it threw, answered wrongly, hung) is left out with
     * its one line, its name added to {@code skipped}. A study stopped otherwise says where its
     * finished rows are.
     */
    private List<Tradeoff.Result> measureAll(Tradeoff t, List<Variant> variants, StudyFile table, Path csvOut, List<String> skipped)
            throws java.io.IOException {
        List<Tradeoff.Result> results = new ArrayList<>();
        BuilderFault firstFault = null;
        try (ProgressBar bar = progress.bar(variants.size(), "variants")) {
            for (int i = 0; i < variants.size(); i++) {
                bar.step(i, variants.get(i).name());
                Tradeoff.Result r;
                try {
                    r = t.run(variants.get(i));
                } catch (BuilderFault fault) {
                    if (firstFault == null) firstFault = fault;
                    skipped.add(variants.get(i).name());
                    bar.print(System.out, String.format(Locale.ROOT, "%-22s skipped: %s", variants.get(i).name(), fault.getMessage()));
                    continue;
                }
                results.add(r);
                table.progress(Tradeoff.csv(results));
                bar.print(System.out, String.format(Locale.ROOT,
                        "%-22s %10.1f %10.2f %9d %8.1f %8.1f %8.1f %9.3f %11.0f %11.0f %11.0f", r.variant(), r.buildMs(),
                        r.expectedCost(), r.nodes(), r.nodesPerRay(), r.testsPerRay(), r.boxesPerRay(), r.raysPerSecond() / 1e6,
                        r.totalMs(1), r.totalMs(10), r.totalMs(100)));
            }
        } catch (RuntimeException | Error stopped) {
            if (!results.isEmpty())
                System.err.println("(the study stopped; its " + results.size() + " finished row" + (results.size() == 1 ? " is" : "s are")
                        + " in " + table.partial() + ", and " + csvOut + " is as it was)");
            throw stopped;
        }
        if (results.isEmpty()) throw firstFault;
        return results;
    }
}
