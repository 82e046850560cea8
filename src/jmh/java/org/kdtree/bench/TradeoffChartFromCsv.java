package org.kdtree.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.kdtree.tradeoff.TradeoffChart;
import org.kdtree.tradeoff.TradeoffResult;

/**
 * Redraws a trade-off chart from the CSV the {@code tradeoff} command wrote, so that a chart can
 * be improved without measuring again. The CSV keeps rays per second and build times, not the
 * triangle count, which is given on the command line.
 *
 * <pre>
 * java -cp target/benchmarks.jar org.kdtree.bench.TradeoffChartFromCsv docs/tradeoff/bunny-R.csv 69451 \
 *      "stanford-bunny: build time vs trace time (R rays)" \
 *      "stanford-bunny, 69,451 triangles; R rays x 100,000; 1 build thread, 2 cores; measured 2026-11-29" \
 *      docs/tradeoff/bunny-R.png
 * </pre>
 */
public final class TradeoffChartFromCsv {
    private TradeoffChartFromCsv() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length != 5) {
            System.err.println("usage: TradeoffChartFromCsv RESULTS.csv TRIANGLES TITLE CAPTION OUT.png");
            System.exit(2);
        }
        int triangles = Integer.parseInt(args[1]);
        List<TradeoffResult> results = new ArrayList<>();
        List<String> lines = Files.readAllLines(Path.of(args[0]));
        for (String line : lines.subList(1, lines.size())) {
            String[] f = line.split(",", 14);   // the last field, the settings, is quoted and may hold commas
            results.add(new TradeoffResult(f[0], f[13], Double.parseDouble(f[1]), Double.parseDouble(f[2]),
                    Integer.parseInt(f[3]), Integer.parseInt(f[4]), Long.parseLong(f[5]), Double.parseDouble(f[6]),
                    Double.parseDouble(f[7]), Double.parseDouble(f[8]) * 1e6, triangles));
        }
        TradeoffChart.write(results, args[2], 10, args[3] + " · data: " + Path.of(args[0]).getFileName(), Path.of(args[4]));
    }
}
