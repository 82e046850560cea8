package org.kdtree.architecture;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * docs/images/packages.dot and packages.svg, the package graph of docs/architecture.md, must show
 * the code as it is. Redraw them (after changing the packages' uses or layers) with
 * {@code mvn -B -q test -Dtest=PackageGraphTest -Dpackage.graph.update=true}.
 */
class PackageGraphTest {
    static final Path DOT = Path.of("docs/images/packages.dot"), SVG = Path.of("docs/images/packages.svg");

    @Test void theCommittedPicturesShowTheCodeAsItIs() throws Exception {
        PackageGraph graph = new PackageGraph(PackageImports.read(), Layers.read());
        String dot = graph.dot(), svg = graph.svg();
        if (Boolean.getBoolean("package.graph.update")) {
            Files.createDirectories(DOT.getParent());
            Files.writeString(DOT, dot);
            Files.writeString(SVG, svg);
        }
        String redraw = "stale: redraw with mvn -B -q test -Dtest=PackageGraphTest -Dpackage.graph.update=true";
        assertThat(Files.exists(DOT) ? Files.readString(DOT) : "").as(DOT + " " + redraw).isEqualTo(dot);
        assertThat(Files.exists(SVG) ? Files.readString(SVG) : "").as(SVG + " " + redraw).isEqualTo(svg);
    }

    @Test void theDrawingLeavesOutOnlyUsesThatOthersImply() {
        PackageGraph graph = new PackageGraph(PackageImports.read(), Layers.read());
        assertThat(graph.reducedEdges()).extracting(e -> e[0] + "->" + e[1])
                .contains("io->scene", "render->scene", "scene->shape").doesNotContain("render->geom", "io->render");
        assertThat(graph.dot()).contains("render -> geom", "io -> scene");
    }
}
