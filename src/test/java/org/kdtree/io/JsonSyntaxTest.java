package org.kdtree.io;

import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.StringReader;
import org.junit.jupiter.api.Test;

/** Malformed JSON is explained in a user's terms, never with gson's advice to programmers. */
class JsonSyntaxTest {
    private static void refused(String json, String expected) {
        assertThatThrownBy(() -> JsonNode.read(new StringReader(json), "s.json")).isInstanceOf(SceneFormatException.class)
                .hasMessage(expected);
    }

    @Test void theUsualMistakes() {
        refused("{\"a\": [1, 2,]}", "s.json:1: malformed JSON: a comma before ']' (JSON allows no trailing comma) (column 13)");
        refused("{\n  // a comment\n  \"a\": 1}", "s.json:2: malformed JSON: comments are not allowed (column 3)");
        refused("{'a': 1}", "s.json:1: malformed JSON: strings and names need double quotes, not single ones (column 2)");
        refused("{a: 1}", "s.json:1: malformed JSON: a name or text without double quotes (column 2)");
        refused("{\"a\": [0, 0 5]}", "s.json:1: malformed JSON: expected ',' or ']' (column 13)");
    }

    @Test void deepNestingIsRefusedNotAStackOverflow() {
        refused("[".repeat(100_000), "s.json:1: arrays and objects nested deeper than 64 levels; a scene needs no more than 4");
    }
}
