package org.kdtree.spec;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.kdtree.accel.SharedSettings;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.generate.Meshes;
import org.kdtree.kdtree.CyclingAxisBuilder;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.kdtree.MedianPlaneBuilder;
import org.kdtree.kdtree.Quality;
import org.kdtree.kdtree.SahBuilder;
import org.kdtree.kdtree.SahSettings;
import org.kdtree.kdtree.SlidingMidpointBuilder;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.testing.Trees;

/** One builder specification: one validation, one rule for settings that do not apply, any registered builder. */
class BuilderSpecTest {
    private static final TriangleMesh MESH = Meshes.cornerClusters(2000, 7);

    @Test void theFluentApiChainsEachBuildersOwnSettersIntoTheBaseOnes() {
        MedianPlaneBuilder median = new MedianPlaneBuilder();
        median.minPrimitives(1).threads(4);
        assertThat(median.threads()).isEqualTo(4);
        assertThat(median.minPrimitives()).isEqualTo(1);
        SlidingMidpointBuilder sliding = new SlidingMidpointBuilder().leafSize(4);
        sliding.threads(2).perfectSplits(false);
        assertThat(sliding.leafSize()).isEqualTo(4);
        SahBuilder sah = new SahBuilder().lambda(0.5);
        sah.costModel(new org.kdtree.accel.CostModel(10, 20));
        assertThat(sah.lambda()).isEqualTo(0.5);
    }

    @Test void aSpecBuildsTheTreeOfTheSameFluentSettings() {
        BuilderSpec spec = BuilderSpec.of("sah").with(SahSettings.LAMBDA, 0.5).with(SahSettings.ALGORITHM, SahBuilder.Algorithm.BINNED)
                .with(SharedSettings.BINS, 8).with(SharedSettings.KT, 10.0).with(KdTreeBuilder.PERFECT_SPLITS, false).with(SharedSettings.MAX_DEPTH, 14);
        KdTreeBuilder fluent = new SahBuilder().lambda(0.5).algorithm(SahBuilder.Algorithm.BINNED).bins(8).costs(10, 20)
                .perfectSplits(false).maxDepth(14);
        KdTreeBuilder made = spec.create();
        assertThat(made.describeSettings()).isEqualTo(fluent.describeSettings());
        Trees.assertSameTree(made.build(MESH), fluent.build(MESH));
        assertThat(spec).hasToString("sah --kt 10.0 --max-depth 14 --no-perfect-splits --lambda 0.5 --algorithm BINNED --bins 8");
    }

    @Test void aPresetComesFirstSoThatAnExplicitDepthOverridesIt() {
        KdTreeBuilder b = BuilderSpec.of("sah").with(SharedSettings.MAX_DEPTH, 5).with(SahSettings.QUALITY, Quality.FAST).create();
        assertThat(b.maxDepth()).isEqualTo(5);
        assertThat(((SahBuilder) b).leafBelow()).isEqualTo(Quality.FAST.leafBelow());
    }

    @Test void aValueOutOfRangeIsRefusedWhenGivenNamingTheSetting() {
        assertThatThrownBy(() -> BuilderSpec.of("sah").with(SahSettings.LAMBDA, 2.0))
                .hasMessage("lambda must be between 0.01 and 1, got 2");
        assertThatThrownBy(() -> BuilderSpec.of("median-plane").with(CyclingAxisBuilder.MIN_PRIMITIVES, -1))
                .hasMessageStartingWith("Kmintri must be between 0 and");
    }

    @Test void aSettingThatDoesNotApplyIsRefusedNotIgnoredNamingTheSetting() {
        assertThatThrownBy(() -> BuilderSpec.of("median-plane").with(SahSettings.LAMBDA, 0.5).with(SharedSettings.BINS, 8).create())
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessage("lambda applies to the sah builder only, not to median-plane");
        assertThatThrownBy(() -> BuilderSpec.of("median-plane").with(SharedSettings.BINS, 8).create())
                .hasMessage("bins applies to the sah and bvh builders only, not to median-plane");
        assertThatThrownBy(() -> BuilderSpec.of("bvh").with(SahSettings.LAMBDA, 0.5).structureBuilder())
                .hasMessage("lambda applies to the sah builder only, not to bvh");
        assertThatThrownBy(() -> BuilderSpec.of("bvh").with(KdTreeBuilder.PERFECT_SPLITS, false).structureBuilder())
                .hasMessage("perfect splits applies to the kd-tree builders only, not to bvh");
        assertThatThrownBy(() -> BuilderSpec.of("sah").with(BvhBuilder.WIDTH, 8).create())
                .hasMessage("BVH width applies to the bvh builder only, not to sah");
        assertThatThrownBy(() -> BuilderSpec.of("sah").with(CyclingAxisBuilder.MIN_PRIMITIVES, 1).create())
                .hasMessage("Kmintri applies to the median-plane and object-median builders only, not to sah");
        assertThatThrownBy(() -> BuilderSpec.of("sah").with(SharedSettings.LEAF_SIZE, 4).create())
                .hasMessage("leaf size applies to the sliding-midpoint and bvh builders only, not to sah");
    }

    @Test void carryingSettingsToAnotherBuilderKeepsThoseThatApply() {
        BuilderSpec sah = BuilderSpec.of("sah").with(SahSettings.LAMBDA, 0.5).with(SharedSettings.KT, 3.0);
        BuilderSpec median = sah.forBuilder("median-plane");
        assertThat(median.get(SahSettings.LAMBDA)).isNull();
        assertThat(median.get(SharedSettings.KT)).isEqualTo(3.0);
        assertThat(median.create().costModel().kt()).isEqualTo(3.0);
        assertThat(median.forBuilder("sah").get(SahSettings.LAMBDA)).as("dropped, not remembered").isNull();
    }

    @Test void valuesNotGivenAreTheBuildersDefaults() {
        BuilderSpec sah = BuilderSpec.of("sah");
        assertThat(sah.value(SahSettings.LAMBDA)).isEqualTo(0.8);
        assertThat(sah.value(SahSettings.ALGORITHM)).isEqualTo(SahBuilder.Algorithm.EVENT);
        assertThat(sah.value(CyclingAxisBuilder.MIN_PRIMITIVES)).as("sah takes no Kmintri").isNull();
        assertThat(BuilderSpec.applies(CyclingAxisBuilder.MIN_PRIMITIVES, "object-median")).isTrue();
        assertThat(BuilderSpec.applies(SharedSettings.BINS, "median-plane")).isFalse();
        assertThat(BuilderSpec.of("sah").with(SharedSettings.KT, 15.0)).isNotEqualTo(sah)
                .isEqualTo(BuilderSpec.of("sah").with(SharedSettings.KT, 15.0));
    }

    /** The course example is declared in META-INF/services only: the spec finds it by name, with the settings every builder takes. */
    @Test void aBuilderOnTheClassPathIsCreatedByNameWithTheCommonSettings() {
        KdTreeBuilder b = BuilderSpec.of("centre-midpoint").with(SharedSettings.THREADS, 2).with(SharedSettings.MAX_DEPTH, 9).create();
        assertThat(b.name()).isEqualTo("centre-midpoint");
        assertThat(b.threads()).isEqualTo(2);
        assertThat(b.maxDepth()).isEqualTo(9);
        assertThatThrownBy(() -> BuilderSpec.of("centre-midpoint").with(SahSettings.LAMBDA, 0.5).create())
                .hasMessage("lambda applies to the sah builder only, not to centre-midpoint");
        assertThatThrownBy(() -> BuilderSpec.of("nothing").create()).hasMessageStartingWith("unknown builder 'nothing'");
    }
}
