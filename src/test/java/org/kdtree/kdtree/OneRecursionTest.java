package org.kdtree.kdtree;

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
import org.kdtree.generate.Meshes;
import org.kdtree.shape.Primitives;
import org.kdtree.spec.Builders;

/**
 * Algorithm 1 is written once (KdTreeBuilder.recConst) and every builder runs through it: every
 * node of every tree, whatever the builder, algorithm or thread count, was visited by that
 * recursion, which reports each node it visits to the build's watch.
 */
class OneRecursionTest {
    private static final Path MAIN = Path.of("src/main/java");

    @Test void recConstIsWrittenOnceInTheMainCode() throws IOException {
        Pattern declaration = Pattern.compile("\\brecConst\\w*\\s*\\([^)]*\\)\\s*\\{");
        List<String> found = new ArrayList<>();
        try (Stream<Path> files = Files.walk(MAIN)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".java")).toList()) {
                Matcher m = declaration.matcher(Files.readString(f));
                while (m.find()) found.add(MAIN.relativize(f) + ": " + m.group());
            }
        }
        assertThat(found).as("declarations of recConst").hasSize(2)      // the root's, and every node's
                .allMatch(s -> s.startsWith("org/kdtree/kdtree/KdTreeBuilder.java"));
    }

    @Test void noBuilderIsDispatchedOnItsClass() throws IOException {
        try (Stream<Path> files = Files.walk(MAIN.resolve("org/kdtree/kdtree"))) {
            for (Path f : files.filter(p -> p.toString().endsWith(".java")).toList())
                assertThat(Files.readString(f)).as(f.toString()).doesNotContain("getClass() ==").doesNotContain("getClass() !=")
                        .doesNotContain("instanceof SahBuilder");
        }
    }

    /**
     * What a subclass may override: its two answers, its name, its settings' rows and their
     * summary. Package-private methods count too (a library builder in this package could
     * override one, a hidden door a student's builder does not have); a compiler's bridge method
     * is not a method anyone wrote.
     */
    @Test void onlyTerminateFindPlaneAndTheSettingsCanBeOverridden() {
        for (var m : KdTreeBuilder.class.getDeclaredMethods()) {
            int mod = m.getModifiers();
            boolean overridable = !java.lang.reflect.Modifier.isFinal(mod) && !java.lang.reflect.Modifier.isStatic(mod)
                    && !java.lang.reflect.Modifier.isPrivate(mod) && !m.isBridge() && !m.isSynthetic();
            if (overridable) assertThat(m.getName()).as("overridable %s", m)
                    .matches("terminate|findPlane|name|describeSettings|settingRows");
        }
    }

    /** Every registered builder, the SAH's algorithms, one and two threads: the recursion visits every node of the tree. */
    @Test void everyNodeOfEveryBuildersTreeIsVisitedByTheRecursion() {
        Primitives scene = Meshes.cornerClusters(6000, 4);
        List<KdTreeBuilder> builders = new ArrayList<>();
        for (String name : Builders.names()) builders.add(Builders.create(name));
        for (SahBuilder.Algorithm a : SahBuilder.Algorithm.values())
            if (a != SahBuilder.Algorithm.NAIVE) builders.add(new SahBuilder().algorithm(a));
        builders.add(new SahBuilder().threads(2));
        builders.add(new MedianPlaneBuilder().threads(2));
        builders.add(new SahBuilder() { });
        for (KdTreeBuilder b : builders) {
            BuildWatch watch = BuildWatch.watched();
            KdTree tree = b.build(scene, watch);
            assertThat(tree.nodeCount()).as("%s splits", b.name()).isGreaterThan(100);
            assertThat(watch.nodes()).as("%s (%s): nodes visited by recConst", b.name(), b.describeSettings())
                    .isEqualTo(tree.nodeCount());
        }
    }
}
