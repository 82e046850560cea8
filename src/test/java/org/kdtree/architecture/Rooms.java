package org.kdtree.architecture;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Each audience's code in its own room, lowest first: the library a user builds on, the
 * rendering on top of it, the course (contract, checks, the worked example) and the applications
 * (command line, workbench, studies). A room may use its own and lower rooms only, so a library
 * user never pulls in the course or an application, and docs/architecture.md's "Rooms" says the
 * same. The rooms are coarser than the layers: the layers order packages, the rooms audiences.
 */
final class Rooms {
    /** Room name to its packages, lowest room first. */
    static final Map<String, List<String>> ROOMS = rooms();

    private Rooms() {
    }

    private static Map<String, List<String>> rooms() {
        Map<String, List<String>> rooms = new LinkedHashMap<>();
        rooms.put("library", List.of("limits", "geom", "files", "shape", "accel", "kdtree", "bvh", "spec", "generate",
                "points", "collide", "compare", "scene", "io", "treefile"));
        rooms.put("rendering", List.of("render"));
        rooms.put("course", List.of("check", "examples"));
        rooms.put("applications", List.of("measure", "tradeoff", "gui", "cli"));
        return rooms;
    }

    /** {@return each package's room index, 0 the library} */
    static Map<String, Integer> indexOfPackage() {
        Map<String, Integer> index = new LinkedHashMap<>();
        int room = 0;
        for (List<String> packages : ROOMS.values()) {
            for (String p : packages) index.put(p, room);
            room++;
        }
        return index;
    }

    /** {@return the room's name at an index} */
    static String name(int index) {
        return List.copyOf(ROOMS.keySet()).get(index);
    }
}
