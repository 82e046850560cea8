package org.kdtree.check;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.catchThrowable;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.util.Arrays;
import java.util.function.Supplier;
import org.junit.jupiter.api.Test;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.testing.PlaneOutsideBuilder;
import org.kdtree.testing.PluginMidpointBuilder;

/** A graded builder's builds recorded where its code runs and replayed into the same checks where the grade is made. */
class TreeTapeTest {
    private static ContractCase named(String name) {
        return Contract.cases().stream().filter(c -> c.name().equals(name)).findFirst().orElseThrow();
    }

    /** Runs {@code c} recording {@code builder}'s builds; {@return the tape} */
    private static byte[] record(ContractCase c, Supplier<KdTreeBuilder> builder) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        TreeTape.Recorder tape = new TreeTape.Recorder(out, builder.get());
        Contract.withTape(tape, () -> {
            try {
                c.run(builder);
            } catch (ContractViolation expected) {
                // the replay must fail the same way
            }
        });
        tape.end();
        return out.toByteArray();
    }

    /** Replays {@code tape} into {@code c}; {@return what the case threw, or null} */
    private static Throwable replay(ContractCase c, byte[] tape) {
        TreeTape.Player player = new TreeTape.Player(new ByteArrayInputStream(tape));
        Throwable[] thrown = {null};
        Contract.withTape(player, () -> thrown[0] = catchThrowable(() -> c.run(player::builder)));
        if (thrown[0] == null) player.end();
        return thrown[0];
    }

    @Test void aSoundBuildersTreesPassOnTheTrustedSide() {
        ContractCase c = named("uniform triangles");
        byte[] tape = record(c, PluginMidpointBuilder::new);
        assertThat(tape.length).isGreaterThan(1000);
        assertThat(replay(c, tape)).isNull();
    }

    @Test void aBrokenBuildersReplayFailsWithTheMessageItsOwnRunGives() {
        ContractCase c = named("mixed 2-D shapes");
        Throwable inPlace = catchThrowable(() -> c.run(PlaneOutsideBuilder::new));
        Throwable replayed = replay(c, record(c, PlaneOutsideBuilder::new));
        assertThat(inPlace).isInstanceOf(ContractViolation.class).hasMessageContaining("outside the voxel");
        assertThat(replayed).isInstanceOf(ContractViolation.class).hasMessage(inPlace.getMessage());
    }

    @Test void aTapeOfOtherBuildsIsAMismatchNamingBoth() {
        byte[] tape = record(named("uniform triangles"), PluginMidpointBuilder::new);
        assertThat(replay(named("corner clusters"), tape)).isInstanceOf(TreeTape.Mismatch.class)
                .hasMessageContaining("600 uniform triangles").hasMessageContaining("corner clusters");
    }

    @Test void aTapeCutShortIsAnEarlyEndNotAVerdict() {
        ContractCase c = named("uniform triangles");
        byte[] tape = record(c, PluginMidpointBuilder::new);
        Throwable t = replay(c, Arrays.copyOf(tape, tape.length / 2));
        assertThat(t).isInstanceOf(TreeTape.Mismatch.class);
        assertThat(((TreeTape.Mismatch) t).early()).isTrue();
    }

    @Test void bytesAfterTheEndAreCountedAndNotRead() {
        ContractCase c = named("one primitive");
        byte[] tape = record(c, PluginMidpointBuilder::new);
        byte[] more = Arrays.copyOf(tape, tape.length + 39);
        TreeTape.Player player = new TreeTape.Player(new ByteArrayInputStream(more));
        Contract.withTape(player, () -> c.run(player::builder));
        player.end();
        assertThat(player.drainRest()).isEqualTo(39);
    }

    @Test void somethingElseThanATapeIsRefusedAtOnce() {
        assertThatThrownBy(() -> new TreeTape.Player(new ByteArrayInputStream("verdict,,GOOD\n".getBytes())))
                .isInstanceOf(TreeTape.Mismatch.class).hasMessageContaining("does not start as one does");
    }
}
