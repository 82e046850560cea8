package org.kdtree.architecture;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The layers of docs/architecture.md, lowest first: the numbered list under its "## Layers"
 * heading, one line per layer naming its packages in backquotes. The tests hold the code to that
 * list, so the document cannot drift from the code.
 */
final class Layers {
    static final Path DOCUMENT = Path.of("docs/architecture.md");
    private static final Pattern ITEM = Pattern.compile("^(\\d+)\\.\\s+(.*)$");
    private static final Pattern NAME = Pattern.compile("`([a-z0-9]+)`");

    private Layers() {
    }

    /** {@return each package's layer, 0 the lowest, in the document's order} */
    static Map<String, Integer> read() {
        List<String> lines = SourceFiles.read(DOCUMENT).lines().toList();
        int start = lines.indexOf("## Layers");
        if (start < 0) throw new IllegalStateException(DOCUMENT + " has no '## Layers' section");
        Map<String, Integer> layer = new LinkedHashMap<>();
        List<String> items = new ArrayList<>();
        for (int i = start + 1; i < lines.size() && !lines.get(i).startsWith("## "); i++) {
            Matcher item = ITEM.matcher(lines.get(i));
            if (item.matches()) items.add(item.group(2).split(":", 2)[0]);
        }
        for (int l = 0; l < items.size(); l++) {
            Matcher name = NAME.matcher(items.get(l));
            while (name.find()) {
                Integer before = layer.put(name.group(1), l);
                if (before != null) throw new IllegalStateException(DOCUMENT + " puts `" + name.group(1) + "` in two layers");
            }
        }
        return layer;
    }
}
