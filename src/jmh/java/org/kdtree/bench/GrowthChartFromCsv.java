package org.kdtree.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.kdtree.tradeoff.GrowthChart;

/**
 * Draws the growth of build time with N (docs/performance.md) from the CSV files JMH writes
 * ({@code -rf csv}) for {@code BuildBenchmark} and {@code NaiveBuildBenchmark}, with
 * {@code tradeoff.GrowthChart}; a program run by hand, so it lives beside the benchmarks:
 *
 * <pre>
 * java -cp target/benchmarks.jar org.kdtree.bench.GrowthChartFromCsv growth.png surface naive.csv build.csv ...
 * </pre>
 */
public final class GrowthChartFromCsv {
    private GrowthChartFromCsv() {
    }

    /**
     * Reads the CSV files and writes the chart for one scene, exiting with 2 on a usage error and
     * 1 if no row is for the scene.
     *
     * @param args the chart to write (PNG or SVG), the scene, then one or more JMH CSV files
     * @throws IOException if a CSV file cannot be read or is not a build benchmark's, or the chart cannot be written
     */
    public static void main(String[] args) throws IOException {
        if (args.length < 3) {
            System.err.println("usage: GrowthChartFromCsv OUT.png SCENE JMH.csv...");
            System.exit(2);
        }
        String scene = args[1];
        Map<String, TreeMap<Integer, Double>> series = new TreeMap<>();
        for (int i = 2; i < args.length; i++) GrowthChart.read(Path.of(args[i]), scene, series);
        if (series.isEmpty()) {
            System.err.println("no rows for scene " + scene + " in " + String.join(", ", List.of(args).subList(2, args.length)));
            System.exit(1);
        }
        String caption = "JMH averages from " + String.join(", ", List.of(args).subList(2, args.length))
                + " · one build thread · drawn " + java.time.LocalDate.now();
        GrowthChart.write(series, scene, caption, Path.of(args[0]));
        System.out.println("wrote " + args[0]);
    }
}
