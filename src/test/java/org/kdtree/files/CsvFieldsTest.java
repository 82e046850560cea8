package org.kdtree.files;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

/** One line of the project's CSV tables, split as they are written: quotes keep commas, {@code ""} is a quote. */
class CsvFieldsTest {
    @Test void quotedFieldsKeepTheirCommasAndEscapedQuotes() {
        assertThat(CsvFields.of("a.jar,\"Smith, Alice\",s001")).containsExactly("a.jar", "Smith, Alice", "s001");
        assertThat(CsvFields.of("\"say \"\"hi\"\"\",,x")).containsExactly("say \"hi\"", "", "x");
        assertThat(CsvFields.of("")).containsExactly("");
        assertThat(CsvFields.of("1,2,")).containsExactly("1", "2", "");
    }
}
