package org.kdtree.spec;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;
import org.kdtree.kdtree.KdTreeBuilder;

class BuildersTest {
    @Test void theLibrarysBuildersComeFirstThenThoseTheServiceLoaderFinds() {
        // centre-midpoint is named by no code of the library: only by META-INF/services
        assertThat(Builders.names()).containsSubsequence("sah", "median-plane", "object-median", "sliding-midpoint", "centre-midpoint");
        KdTreeBuilder a = Builders.create("centre-midpoint"), b = Builders.create("centre-midpoint");
        assertThat(a.name()).isEqualTo("centre-midpoint");
        assertThat(a).as("a new builder each time: settings are not shared").isNotSameAs(b);
    }

    @Test void anUnknownNameSaysWhichAreKnown() {
        assertThatThrownBy(() -> Builders.create("nope")).hasMessageStartingWith("unknown builder 'nope' (known: sah, ");
    }
}
