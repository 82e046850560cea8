package org.kdtree.architecture;

import java.nio.file.Path;
import java.util.Map;
import java.util.SortedMap;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Which package of org.kdtree uses which, read from the main sources: every import, static
 * import and fully qualified name in code (comments do not count), with the number of files
 * that do so.
 */
final class PackageImports {
    private static final Pattern REFERENCE = Pattern.compile("\\borg\\.kdtree\\.([a-z0-9]+)\\.");

    private PackageImports() {
    }

    /** {@return per package, the packages it uses and in how many of its files}; every package is a key. */
    static SortedMap<String, SortedMap<String, Integer>> read() {
        SortedMap<String, SortedMap<String, Integer>> uses = new TreeMap<>();
        for (Path file : SourceFiles.all()) {
            String source = SourceFiles.read(file);
            String from = SourceFiles.packageOf(source);
            if (from.isEmpty()) continue;
            SortedMap<String, Integer> mine = uses.computeIfAbsent(from, p -> new TreeMap<>());
            Matcher m = REFERENCE.matcher(SourceFiles.code(source));
            java.util.Set<String> seen = new java.util.TreeSet<>();
            while (m.find()) if (!m.group(1).equals(from)) seen.add(m.group(1));
            for (String to : seen) mine.merge(to, 1, Integer::sum);
        }
        for (Map<String, Integer> targets : Map.copyOf(uses).values())
            for (String to : targets.keySet()) uses.computeIfAbsent(to, p -> new TreeMap<>());
        return uses;
    }
}
