package org.kdtree.spec;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.kdtree.accel.Setting;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.kdtree.SahSettings;

/**
 * The builder settings are declared once, in {@link Setting}: docs/limits.md's table of them is
 * made from the rows (regenerate it with
 * {@code mvn -B -q test -Dtest=SettingsTableTest -Dsettings.table.update=true}), and the builders
 * start from the rows' defaults.
 */
class SettingsTableTest {
    private static final Path DOC = Path.of("docs/limits.md");
    private static final String BEGIN = "<!-- builder settings: generated from org.kdtree.spec.SettingsTable by SettingsTableTest -->\n";
    private static final String END = "<!-- end of the builder settings -->\n";

    /** The table docs/limits.md shows: one row per setting, its range (as the other limits are written), default and option. */
    static String table() {
        StringBuilder s = new StringBuilder("| setting | allowed | default | option | applies to | what it does |\n"
                + "| --- | --- | --- | --- | --- | --- |\n");
        for (Setting<?> r : SettingsTable.all()) {
            String allowed = r.limit() != null ? r.limit().range()
                    : r.type() == Boolean.class ? "on, off"
                    : Arrays.stream(r.type().getEnumConstants()).map(Object::toString).collect(Collectors.joining(", "));
            s.append("| ").append(r.name()).append(" | ").append(allowed).append(" | ").append(r.format(r.defaultValue()))
                    .append(" | `").append(r.option()).append("` | ").append(SettingsTable.ownerName(r)).append(" | ").append(r.help()).append(" |\n");
        }
        return s.toString();
    }

    @Test void docsLimitsShowsTheTableOfSettings() throws Exception {
        String doc = Files.readString(DOC);
        int from = doc.indexOf(BEGIN), to = doc.indexOf(END);
        assertThat(from).as("docs/limits.md has the generated table's markers").isGreaterThanOrEqualTo(0).isLessThan(to);
        String fresh = doc.substring(0, from + BEGIN.length()) + table() + doc.substring(to);
        if (Boolean.getBoolean("settings.table.update")) Files.writeString(DOC, doc = fresh);
        assertThat(doc).as("docs/limits.md's builder settings are stale: regenerate with "
                + "mvn -B -q test -Dtest=SettingsTableTest -Dsettings.table.update=true").isEqualTo(fresh);
    }

    @Test void everyBuilderStartsFromTheTablesDefaults() {
        for (String name : Builders.names()) {
            KdTreeBuilder b = Builders.create(name);
            if (!b.getClass().getName().startsWith("org.kdtree.kdtree.")) continue;   // a plug-in may choose its own
            for (Setting<?> s : b.settingRows())
                assertThat(b.settings().get(s)).as(name + " " + s.option()).isEqualTo(s.defaultValue());
        }
    }

    @Test void eachOptionAndNameIsOneSettings() {
        assertThat(SettingsTable.all().stream().map(Setting::option).distinct()).hasSameSizeAs(SettingsTable.all());
        assertThat(SettingsTable.all().stream().map(Setting::name).distinct()).hasSameSizeAs(SettingsTable.all());
        assertThat(SettingsTable.all().get(0)).as("the preset comes first, so that the other settings override it").isSameAs(SahSettings.QUALITY);
    }
}
