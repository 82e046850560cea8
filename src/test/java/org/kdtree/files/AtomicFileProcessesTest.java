package org.kdtree.files;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The file rules across real processes, as a user meets them: two command-line processes writing
 * one file at once never mix, and a process killed outright in the middle of a write leaves the
 * user's file exactly as it was.
 */
class AtomicFileProcessesTest {
    @TempDir Path dir;

    /** A child JVM on this test's class path. */
    private static ProcessBuilder java(String mainClass, String... args) {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx256m", "-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"), mainClass));
        command.addAll(List.of(args));
        return new ProcessBuilder(command).redirectErrorStream(true);
    }

    @Test void twoKnnProcessesWritingOneFileNeverMix() throws Exception {
        Random rnd = new Random(7);
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < 3000; i++) s.append(rnd.nextDouble()).append(',').append(rnd.nextDouble()).append('\n');
        Path pts = Files.writeString(dir.resolve("pts.csv"), s), out = dir.resolve("same.csv");
        for (int round = 0; round < 2; round++) {
            List<Process> runs = new ArrayList<>();
            for (String k : List.of("20", "21"))
                runs.add(java("org.kdtree.cli.Main", "knn", pts.toString(), "--queries", pts.toString(), "--k", k,
                        "--out", out.toString()).redirectOutput(ProcessBuilder.Redirect.DISCARD).start());
            for (Process p : runs) {
                assertThat(p.waitFor(120, TimeUnit.SECONDS)).as("knn finished").isTrue();
                assertThat(p.exitValue()).isZero();
            }
            List<String> lines = Files.readAllLines(out);
            assertThat(lines).hasSize(3000);
            assertThat(lines.stream().map(l -> l.split(",").length).distinct().toList()).as("neighbours per line, round " + round)
                    .singleElement().isIn(20, 21);
        }
        try (Stream<Path> left = Files.list(dir)) {
            assertThat(left.map(p -> p.getFileName().toString()).sorted().toList()).containsExactly("pts.csv", "same.csv");
        }
    }

    /** Writes a big file slowly through {@link AtomicFile}, saying so once it has begun. */
    public static final class SlowWriter {
        public static void main(String[] args) throws IOException {
            AtomicFile.writeText(Path.of(args[0]), out -> {
                for (int i = 0; i < 1_000_000; i++) {
                    out.write("new line " + i + "\n");
                    if (i == 1000) {
                        out.flush();
                        System.out.println("writing");
                        System.out.flush();
                    }
                    if (i > 1000) sleep();
                }
            });
        }

        private static void sleep() {
            try {
                Thread.sleep(1);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    @Test void aProcessKilledInTheMiddleOfAWriteLeavesTheFileAsItWas() throws Exception {
        Path target = Files.writeString(dir.resolve("results.csv"), "the user's results\n");
        byte[] before = Files.readAllBytes(target);
        Process writer = java(SlowWriter.class.getName(), target.toString()).start();
        try (BufferedReader r = new BufferedReader(new InputStreamReader(writer.getInputStream(), StandardCharsets.UTF_8))) {
            assertThat(r.readLine()).as("the child began writing").isEqualTo("writing");
            writer.destroyForcibly();
            assertThat(writer.waitFor(30, TimeUnit.SECONDS)).isTrue();
        }
        assertThat(Files.readAllBytes(target)).as("the target after the kill").isEqualTo(before);
        try (Stream<Path> left = Files.list(dir)) {
            // a kill leaves no chance to clean up: at most the hidden temporary beside it (docs/limits.md)
            assertThat(left.map(p -> p.getFileName().toString()).filter(n -> !n.equals("results.csv")).toList())
                    .allMatch(n -> n.startsWith(".results.csv.") && n.endsWith(".tmp"));
        }
    }
}
