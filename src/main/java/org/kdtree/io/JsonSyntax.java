package org.kdtree.io;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Says in a user's terms what is wrong with JSON that gson refuses. Gson's strict mode reports
 * every such case alike ("Use JsonReader.setLenient(true) to accept malformed JSON"), advice meant
 * for a programmer; the character at the reported column tells the usual mistakes apart.
 */
final class JsonSyntax {
    private static final Pattern WHERE = Pattern.compile("at line (\\d+) column (\\d+)");

    private JsonSyntax() {
    }

    /** The explanation of gson's {@code message} about {@code text}, with the column. */
    static String explain(String message, String text) {
        Matcher m = WHERE.matcher(message == null ? "" : message);
        if (!m.find()) return "malformed JSON";
        int line = Integer.parseInt(m.group(1)), column = Integer.parseInt(m.group(2));
        String where = " (column " + Math.max(1, column - 1) + ")";   // gson counts the column after the character
        if (message.startsWith("Unterminated array")) return "malformed JSON: expected ',' or ']'" + where;
        if (message.startsWith("Unterminated object")) return "malformed JSON: expected ',' or '}'" + where;
        String[] lines = text.split("\n", -1);
        if (line < 1 || line > lines.length) return "malformed JSON" + where;
        String l = lines[line - 1];
        int at = Math.min(Math.max(column - 2, 0), Math.max(l.length() - 1, 0));
        char c = l.isEmpty() ? ' ' : l.charAt(at);
        if (c == '/' || c == '#') return "malformed JSON: comments are not allowed" + where;
        if ((c == ']' || c == '}') && previousNonSpace(lines, line - 1, at) == ',')
            return "malformed JSON: a comma before '" + c + "' (JSON allows no trailing comma)" + where;
        if (c == '\'') return "malformed JSON: strings and names need double quotes, not single ones" + where;
        if (Character.isLetter(c) || c == '_') return "malformed JSON: a name or text without double quotes" + where;
        return "malformed JSON: unexpected '" + c + "'" + where;
    }

    /** The last character before column {@code at} of line {@code index} that is not white space, looking back across lines. */
    private static char previousNonSpace(String[] lines, int index, int at) {
        for (int i = index, j = at - 1; i >= 0; i--, j = i >= 0 ? lines[i].length() - 1 : 0) {
            for (; j >= 0; j--) if (!Character.isWhitespace(lines[i].charAt(j))) return lines[i].charAt(j);
        }
        return ' ';
    }
}
