package org.kdtree.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.ToDoubleFunction;
import org.kdtree.tradeoff.Tradeoff;

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
        List<Tradeoff.Result> results = new ArrayList<>();
        List<String> lines = Files.readAllLines(Path.of(args[0]));
        // Columns by name: files written before boxes_per_ray (a kd-tree's 0) or engine was added have none.
        List<String> header = List.of(lines.get(0).split(","));
        for (String line : lines.subList(1, lines.size())) {
            List<String> f = org.kdtree.files.CsvFields.of(line);
            ToDoubleFunction<String> col = name -> header.contains(name) ? Double.parseDouble(f.get(header.indexOf(name))) : 0;
            java.util.function.Function<String, String> text = name -> header.contains(name) ? f.get(header.indexOf(name)) : "";
            results.add(new Tradeoff.Result(f.get(0), text.apply("settings"), col.applyAsDouble("build_ms"), col.applyAsDouble("expected_cost"),
                    (int) col.applyAsDouble("nodes"), (int) col.applyAsDouble("leaves"), (long) col.applyAsDouble("memory_bytes"),
                    col.applyAsDouble("nodes_per_ray"), col.applyAsDouble("tests_per_ray"), col.applyAsDouble("boxes_per_ray"),
                    col.applyAsDouble("mrays_per_s") * 1e6, triangles, text.apply("engine")));
        }
        Tradeoff.writeChart(results, args[2], 10, args[3] + " · data: " + Path.of(args[0]).getFileName(), Path.of(args[4]));
    }
}
