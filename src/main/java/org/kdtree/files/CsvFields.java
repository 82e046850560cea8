package org.kdtree.files;

import java.util.ArrayList;
import java.util.List;

/**
 * The fields of one line of the CSV tables the project writes and reads back (a class's grades, a
 * roster, a study's rows): each quoted or bare, {@code ""} inside quotes an escaped quote, a comma
 * inside quotes part of the field, no line breaks.
 */
public final class CsvFields {
    private CsvFields() {
    }

    /**
     * {@return the line's fields, in order} (an empty line is one empty field)
     * @param line one line of a CSV table
     */
    public static List<String> of(String line) {
        List<String> out = new ArrayList<>();
        StringBuilder f = new StringBuilder();
        boolean quoted = false;
        for (int i = 0; i < line.length(); i++) {
            char c = line.charAt(i);
            if (quoted && c == '"' && i + 1 < line.length() && line.charAt(i + 1) == '"') {
                f.append('"');
                i++;
            } else if (c == '"') quoted = !quoted;
            else if (c == ',' && !quoted) {
                out.add(f.toString());
                f.setLength(0);
            } else f.append(c);
        }
        out.add(f.toString());
        return out;
    }
}
