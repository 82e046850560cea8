package org.kdtree.cli;

import static org.junit.jupiter.api.Assumptions.assumeTrue;
import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.spec.Builders;
import org.kdtree.testing.InfinitePlaneBuilder;
import org.kdtree.testing.LoopingFindPlaneBuilder;
import org.kdtree.testing.LoopingTerminateBuilder;
import org.kdtree.testing.NaNPlaneBuilder;
import org.kdtree.testing.PlaneOutsideBuilder;
import org.kdtree.testing.PluginJars;
import org.kdtree.testing.SleepyBuilder;
import org.kdtree.testing.ThrowingBuilder;

/**
 * A student's builder that throws, answers with an impossible plane, never returns or crawls:
 * {@code stats} and {@code grade} name it in one line (the builder, the method, the node, what
 * was wrong, a hint), never blame the library, and end. The deadlines are short here, so that
 * the hung and slow builders take a second or two, not the minutes of the defaults.
 */
class BrokenPluginsTest {
    private static final List<Class<?>> BROKEN = List.of(ThrowingBuilder.class, NaNPlaneBuilder.class, InfinitePlaneBuilder.class,
            PlaneOutsideBuilder.class, LoopingTerminateBuilder.class, LoopingFindPlaneBuilder.class, SleepyBuilder.class);
    private static final String[] QUICK = {"--call-deadline", "0.5", "--build-deadline", "1"};
    private static final String N = System.lineSeparator();

    @TempDir static Path dir;
    private static String jar;

    @BeforeAll static void writeTheJar() throws Exception {
        jar = PluginJars.listing(dir, "broken.jar", BROKEN.stream().map(Class::getName).toArray(String[]::new)).toString();
    }

    @AfterAll static void forgetThePlugIns() {
        for (String b : List.of("throws", "nan-plane", "infinite-plane", "plane-outside", "loops-in-terminate", "loops-in-findplane", "sleepy"))
            Builders.remove(b);
    }

    private static CliRun stats(String builder) {
        return CliRun.of(concat("--plugin", jar, "stats", "scenes:talk-figures", "-b", builder));
    }

    private static CliRun grade(String builder) {
        return CliRun.of(concat("--plugin", jar, "grade", "-b", builder));
    }

    private static String[] concat(String... head) {
        String[] all = java.util.Arrays.copyOf(head, head.length + QUICK.length);
        System.arraycopy(QUICK, 0, all, head.length, QUICK.length);
        return all;
    }

    /**
     * The one line each broken builder gets, as a pattern: {@code #} stands for a whole number
     * (a source line, a count), {@code ~} for a measured time.
     */
    private static String line(String builder) {
        return switch (builder) {
            case "throws" -> "builder throws: findPlane threw ArrayIndexOutOfBoundsException (Index 2 out of bounds for length 2)"
                    + " at org.kdtree.testing.ThrowingBuilder.findPlane(ThrowingBuilder.java:#), at depth 0 on a node of 6 primitives;"
                    + " findPlane must return a plane for every node that terminate does not make a leaf";
            case "nan-plane" -> "builder nan-plane: findPlane made an impossible plane (split position must be finite, got NaN)"
                    + " at org.kdtree.testing.NaNPlaneBuilder.findPlane(NaNPlaneBuilder.java:#), at depth 0 on a node of 6 primitives;"
                    + " a plane needs an axis >= 0 and a finite position inside the node's voxel";
            case "infinite-plane" -> "builder infinite-plane: findPlane made an impossible plane (split position must be finite, got"
                    + " Infinity) at org.kdtree.testing.InfinitePlaneBuilder.findPlane(InfinitePlaneBuilder.java:#), at depth 0 on a node"
                    + " of 6 primitives; a plane needs an axis >= 0 and a finite position inside the node's voxel";
            case "plane-outside" -> "builder plane-outside: findPlane chose x0 = 10.4, outside the voxel Box[1.0, 1.0]..[9.4, 9.0],"
                    + " at depth 0 on a node of 6 primitives; findPlane must return a plane on one of the node's axes, inside its voxel";
            case "loops-in-terminate" -> "builder loops-in-terminate: terminate did not return within 0.5 s, at depth 0 on a node of"
                    + " 6 primitives; it was stopped: look for a loop that never ends in terminate";
            case "loops-in-findplane" -> "builder loops-in-findplane: findPlane did not return within 0.5 s, at depth 0 on a node of"
                    + " 6 primitives; it was stopped: look for a loop that never ends in findPlane";
            case "sleepy" -> "builder sleepy: slow: ~ ms per node against ~ ms per node for the library's median plane on this scene;"
                    + " stopped after ~ s at # nodes; look for work repeated on every call (sorting every primitive, sleeping)";
            default -> throw new IllegalArgumentException(builder);
        };
    }

    private static String regex(String line) {
        return java.util.regex.Pattern.quote(line).replace("#", "\\E\\d+\\Q").replace("~", "\\E[0-9.e-]+\\Q");
    }

    private static void statsSaysOneLine(String builder) {
        CliRun r = stats(builder);
        assertThat(r.code()).as(r.err()).isEqualTo(Failure.BUILDER);
        assertThat(r.out()).isEmpty();
        assertThat(r.err()).matches("error: " + regex(line(builder)) + N);
    }

    /** grade: the first check fails with the builder's line; the verdict fails it; no "bug of ours" anywhere. */
    private static CliRun gradeFailsWithOneLine(String builder) {
        CliRun r = grade(builder);
        assertThat(r.code()).as(r.err()).isEqualTo(1);
        assertThat(r.out()).containsPattern("(?m)^  talk figures +FAIL  " + regex(line(builder) + " (building the talk figures)") + "$")
                .contains("verdict: FAIL: breaks the contract (").doesNotContain("bug of ours");
        return r;
    }

    @Test void aBuilderThatThrowsIsNamedWithItsMethodAndNode() {
        statsSaysOneLine("throws");
        gradeFailsWithOneLine("throws");
    }

    @Test void impossiblePlanesAreTheBuildersBadAnswers() {
        for (String b : List.of("nan-plane", "infinite-plane", "plane-outside")) {
            statsSaysOneLine(b);
            gradeFailsWithOneLine(b);
        }
    }

    @Test void aHungBuilderIsStoppedAndTheRestOfGradingIsNotRun() {
        // Stopping a hung builder's thread needs Thread.stop, which JDK 20 removed: CI's JDK 17 run checks it.
        assumeTrue(Runtime.version().feature() < 20, "Thread.stop works up to JDK 19");
        for (String b : List.of("loops-in-terminate", "loops-in-findplane")) {
            statsSaysOneLine(b);
            String method = b.endsWith("terminate") ? "terminate" : "findPlane";
            CliRun r = gradeFailsWithOneLine(b);
            assertThat(r.out()).contains("  mixed 2-D shapes                             not run  builder " + b + " hung in " + method
                            + " (see talk figures)")
                    .contains("verdict: FAIL: breaks the contract (1 of 18 checks: talk figures); 17 not run: builder " + b
                            + " hung in " + method + " (see talk figures)")
                    .doesNotContain("never stops");
        }
    }

    @Test void aSlowBuilderIsReportedAsSlowAgainstTheMedianPlane() {
        statsSaysOneLine("sleepy");
        CliRun r = gradeFailsWithOneLine("sleepy");
        assertThat(r.out()).contains("not run  builder sleepy is too slow (see talk figures)").doesNotContain("never stops");
    }
}
