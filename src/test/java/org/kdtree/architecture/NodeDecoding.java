package org.kdtree.architecture;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Finds code that decodes a kd-tree's node words by hand instead of through {@code tree.Nodes}:
 * indexing the node array, masking or shifting a node's word or the tree's axis-field width, or
 * asking for a leaf mark. It reads code as {@link SourceFiles#code} leaves it (no comments, no
 * strings) and follows the names a file binds to {@code nodeArray()}, {@code axisBits()} and
 * {@code Nodes.word(...)}, and to the node array's elements.
 */
final class NodeDecoding {
    /** A name bound to one of the calls: {@code name = ... call(}, up to the end of the statement. */
    private static final String BOUND = "\\b(\\w+)\\s*=\\s*[^;=]*?\\b";
    private static final Pattern NODE_ARRAY = Pattern.compile(BOUND + "nodeArray\\s*\\(\\s*\\)");
    private static final Pattern AXIS_BITS = Pattern.compile(BOUND + "axisBits\\s*\\(\\s*\\)");
    private static final Pattern LEAF_MARK = Pattern.compile(BOUND + "leafMark\\s*\\(\\s*\\)");
    private static final Pattern WORD = Pattern.compile(BOUND + "Nodes\\s*\\.\\s*word\\s*\\(");
    /** A bit operator: shifts, and single {@code & | ^} (not {@code && ||}, not compound assignment). */
    private static final String BIT_OP = "(?:<<|>>>?|(?<![&|])[&|^](?![&|=]))";
    /** What is layout knowledge whatever the names: a node array indexed straight from the call, a leaf mark. */
    private static final Pattern ALWAYS = Pattern.compile("nodeArray\\s*\\(\\s*\\)\\s*\\[|\\bleafMark\\b"
            + "|axisBits\\s*\\(\\s*\\)\\s*" + BIT_OP + "|" + BIT_OP + "\\s*[\\w.()]*\\baxisBits\\s*\\(\\s*\\)");

    private NodeDecoding() {
    }

    /** {@return each hand decoding in {@code code}, as the matched text} */
    static List<String> in(String code) {
        List<String> found = new ArrayList<>();
        find(ALWAYS, code, found);
        Set<String> decoded = names(AXIS_BITS, code);
        decoded.addAll(names(LEAF_MARK, code));
        decoded.addAll(names(WORD, code));
        for (String array : names(NODE_ARRAY, code)) {
            Pattern indexed = Pattern.compile("\\b" + array + "\\s*\\[");
            find(indexed, code, found);
            decoded.addAll(names(Pattern.compile(BOUND + indexed.pattern()), code)); // words read by hand
        }
        for (String name : decoded)
            find(Pattern.compile(BIT_OP + "\\s*" + name + "\\b|\\b" + name + "\\s*" + BIT_OP), code, found);
        return found;
    }

    /** The names bound to {@code call}, and the names bound to those in turn ({@code int[] n = this.nodes;}). */
    private static Set<String> names(Pattern call, String code) {
        Set<String> names = new LinkedHashSet<>();
        Matcher m = call.matcher(code);
        while (m.find()) names.add(m.group(1));
        for (String name : List.copyOf(names)) {
            Matcher alias = Pattern.compile("\\b(\\w+)\\s*=\\s*(?:this\\s*\\.\\s*)?" + name + "\\s*;").matcher(code);
            while (alias.find()) names.add(alias.group(1));
        }
        return names;
    }

    private static void find(Pattern p, String code, List<String> found) {
        Matcher m = p.matcher(code);
        while (m.find()) found.add(m.group().strip());
    }
}
