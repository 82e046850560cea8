package org.kdtree.spec;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.catchThrowable;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.accel.Setting;
import org.kdtree.generate.Points;
import org.kdtree.kdtree.SahBuilder;
import org.kdtree.kdtree.SahSettings;
import org.kdtree.measure.RayBatch;

/**
 * Issue 34, item 11: a library user never typed {@code --lambda}, so the library's errors name
 * each setting as docs/limits.md does ("lambda must be between 0.01 and 1, got 2"); the command
 * line words the same refusal with the option the user typed ({@link Setting.Refused#message},
 * cli.FailureTest and BvhCommandsTest see the options).
 */
class LibraryMessagesTest {
    /** A value past each number row's range, refused by the spec and by the row, in words without an option. */
    @Test void everyRowOutOfRangeIsNamedByItsNameNotItsOption() {
        List<String> wrong = new ArrayList<>();
        for (Setting<?> row : SettingsTable.all()) {
            if (row.limit() == null) continue;
            Object tooBig = row.type() == Integer.class ? (Object) (int) Math.min(Integer.MAX_VALUE, row.limit().max() + 1)
                    : (Object) (row.limit().max() + 1);
            Throwable t = catchThrowable(() -> row.check(tooBig));
            assertThat(t).as(row.name()).isInstanceOf(Setting.Refused.class);
            if (!t.getMessage().startsWith(row.name() + " must be between ") || t.getMessage().contains("--"))
                wrong.add(t.getMessage());
            assertThat(((Setting.Refused) t).message(Setting::option)).startsWith(row.option() + " must be between ");
            assertThat(((Setting.Refused) t).settings()).containsExactly(row);
        }
        assertThat(wrong).as("library messages that name an option, not the setting").isEmpty();
    }

    @Test void theApiAndTheSpecNameTheSetting() {
        assertThatThrownBy(() -> new SahBuilder().lambda(2)).hasMessage("lambda must be between 0.01 and 1, got 2");
        assertThatThrownBy(() -> BuilderSpec.of("sah").with(SahSettings.LAMBDA, 2.0)).hasMessage("lambda must be between 0.01 and 1, got 2");
        assertThatThrownBy(() -> new SahBuilder().threads(0)).hasMessage("threads must be between 1 and 256, got 0");
        assertThatThrownBy(() -> new RayBatch(0, () -> null)).hasMessage("threads must be between 1 and 256, got 0");
        assertThatThrownBy(() -> Points.named("gaussian", 1, 1, 1)).hasMessageNotContaining("--");
        assertThatThrownBy(() -> BuilderSpec.of("bvh").create())   // the command line's "-b bvh builds ..." is cli.BvhCommandsTest's
                .hasMessageStartingWith("the bvh builder makes a bounding volume hierarchy, which answers ray queries only").hasMessageNotContaining("-b ");
    }

    /** Every row given to a builder that does not take it: the refusal names the rows, and the command line's wording the options. */
    @Test void aRowABuilderDoesNotTakeIsNamedByItsName() {
        for (String builder : BuilderSpec.names())
            for (Setting<?> row : SettingsTable.all()) {
                if (BuilderSpec.applies(row, builder)) continue;
                Throwable t = catchThrowable(() -> given(BuilderSpec.of(builder), row).structureBuilder());
                assertThat(t).as(row.name() + " on " + builder).isInstanceOf(Setting.Refused.class)
                        .hasMessageStartingWith(row.name() + " applies to ").hasMessageNotContaining("--");
                assertThat(((Setting.Refused) t).message(Setting::option)).startsWith(row.option() + " applies to ");
            }
    }

    @Test void aPluginIsNamedByItsFileNotByTheOption(@TempDir Path dir) throws Exception {
        Path notes = Files.writeString(dir.resolve("notes.jar"), "not a zip");
        assertThatThrownBy(() -> Builders.loadPlugins(notes)).hasMessage(notes + ": not a jar (zip) file");
        assertThatThrownBy(() -> Builders.loadPlugins(dir.resolve("missing"))).hasMessage(dir.resolve("missing") + ": no such jar or folder");
    }

    @SuppressWarnings("unchecked")
    private static <T> BuilderSpec given(BuilderSpec spec, Setting<T> row) {
        Object v = row.defaultValue();
        if (v == null) v = row.type().getEnumConstants()[0];
        if (v instanceof Boolean b) v = !b;
        return spec.with(row, (T) v);
    }
}
