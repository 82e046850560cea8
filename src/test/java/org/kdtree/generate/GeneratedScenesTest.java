package org.kdtree.generate;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.kdtree.io.BundledScenes;
import org.kdtree.shape.PointsKd;
import org.kdtree.shape.TriangleMesh;

/** A scene's name means one scene: the bundled files are the generated scenes of their names, a seed gives one scene. */
class GeneratedScenesTest {
    @Test void theBundledWorkbenchScenesAreTheGeneratedScenesOfTheirNames() {
        assertThat(BundledScenes.read2D("uniform-200.scene2d").shapes()).isEqualTo(Shapes.named("uniform", 200).shapes());
        assertThat(BundledScenes.read2D("clustered-200.scene2d").shapes()).isEqualTo(Shapes.named("clustered", 200).shapes());
        assertThat(BundledScenes.read2D("overlapping-60.scene2d").shapes()).isEqualTo(Shapes.named("overlapping", 60).shapes());
        assertThat(BundledScenes.read2D("long-thin.scene2d").shapes()).isEqualTo(Shapes.longThin().shapes());
    }

    @Test void aSeedGivesOneSceneAndAnotherSeedAnother() {
        assertThat(Meshes.clustered(500, 7).vertices()).isEqualTo(Meshes.clustered(500, 7).vertices())
                .isNotEqualTo(Meshes.clustered(500, 8).vertices());
        assertThat(Meshes.named("clustered", 500).vertices()).isEqualTo(Meshes.clustered(500, 2).vertices());
        assertThat(Shapes.named("mixed", 100).shapes()).isEqualTo(Shapes.mixed(100, Shapes.SEED).shapes()).isNotEqualTo(Shapes.mixed(100, 2).shapes());
        assertThat(coords(Points.clustered(100, 3, 5))).isEqualTo(coords(Points.clustered(100, 3, 5)));
        assertThatThrownBy(() -> Meshes.named("gaussian", 10)).hasMessageContaining("uniform, clustered, surface");
    }

    /** Clustered means tight clusters with empty space between, in 3-D as for points. */
    @Test void clusteredScenesHoldTightClustersWithEmptySpaceBetween() {
        TriangleMesh m = Meshes.clustered(2000, 0.02, 3);
        int nearACluster = 0;
        for (int t = 0; t < m.size(); t++) if (distanceToOthers(m, t) < 0.5) nearACluster++;
        assertThat(nearACluster).isGreaterThan(1900);
        PointsKd p = Points.clustered(2000, 4, 3), q = Points.clusteredQueries(200, 4, 3);
        for (int i = 0; i < q.size(); i++) assertThat(nearest(p, q, i)).as("query %d", i).isLessThan(0.2);
        PointsKd u = Points.uniform(200, 4, 3);
        int far = 0;
        for (int i = 0; i < u.size(); i++) if (nearest(p, u, i) > 0.2) far++;
        assertThat(far).as("uniform points far from every cluster").isGreaterThan(100);
    }

    @Test void theContractsFlatSceneLiesInOnePlaneAndItsCornerClustersSpanTheUnitCube() {
        double[] v = Meshes.flat(300, 6).vertices();
        for (int i = 2; i < v.length; i += 3) assertThat(v[i]).isEqualTo(0.5);
        TriangleMesh corners = Meshes.cornerClusters(100, 4);
        assertThat(corners.size()).isEqualTo(102);
        assertThat(MeshGrid.vertexBounds(corners).extent(0)).isEqualTo(1.0);
    }

    private static double[] coords(PointsKd p) {
        double[] c = new double[p.size() * p.dimension()];
        for (int i = 0; i < p.size(); i++) for (int a = 0; a < p.dimension(); a++) c[i * p.dimension() + a] = p.coord(i, a);
        return c;
    }

    /** The distance from triangle t's first corner to the nearest first corner of another triangle. */
    private static double distanceToOthers(TriangleMesh m, int t) {
        double best = Double.POSITIVE_INFINITY;
        for (int s = 0; s < m.size(); s++) {
            if (s == t) continue;
            double d = 0;
            for (int a = 0; a < 3; a++) d += Math.pow(m.corner(t, 0, a) - m.corner(s, 0, a), 2);
            best = Math.min(best, d);
        }
        return Math.sqrt(best);
    }

    private static double nearest(PointsKd data, PointsKd from, int i) {
        double best = Double.POSITIVE_INFINITY;
        for (int j = 0; j < data.size(); j++) {
            double d = 0;
            for (int a = 0; a < data.dimension(); a++) d += Math.pow(data.coord(j, a) - from.coord(i, a), 2);
            best = Math.min(best, d);
        }
        return Math.sqrt(best);
    }
}
