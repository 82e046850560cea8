package org.kdtree.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Issue 46, item 8: a JMH user reads in the README what each benchmark's parameters are and how
 * many combinations a run with none picked makes, read here from the benchmarks' own sources.
 */
class BenchmarksInReadmeTest {
    private static final Pattern PARAM = Pattern.compile("@Param\\(\\{([^}]*)}\\)\\s*public\\s+\\w+\\s+(\\w+);");

    @Test void everyBenchmarksParametersAndCombinationsAreInTheReadme() throws IOException {
        String readme = Files.readString(Path.of("README.md"));
        List<String> wrong = new ArrayList<>();
        try (Stream<Path> sources = Files.list(Path.of("src/jmh/java/org/kdtree/bench"))) {
            for (Path source : sources.filter(f -> f.toString().endsWith("Benchmark.java")).sorted().toList()) {
                String name = source.getFileName().toString().replace(".java", "");
                Matcher m = PARAM.matcher(Files.readString(source));
                long combinations = 1;
                List<String> params = new ArrayList<>();
                while (m.find()) {
                    combinations *= m.group(1).split(",").length;
                    params.add(m.group(2));
                }
                if (params.isEmpty()) continue;
                String row = readme.lines().filter(l -> l.startsWith("| `" + name + "`")).findFirst().orElse(null);
                if (row == null) { wrong.add(name + ": no row in the README's table"); continue; }
                for (String p : params) if (!row.contains("`" + p + "`")) wrong.add(name + ": parameter " + p + " not explained");
                if (!row.strip().endsWith("| " + combinations + " |")) wrong.add(name + ": " + combinations + " combinations, the row says otherwise: " + row);
            }
        }
        assertThat(wrong).isEmpty();
        assertThat(readme).as("a first run that picks one combination").containsPattern("benchmarks\\.jar \\S*BuildBenchmark\\S* -p ");
    }
}
