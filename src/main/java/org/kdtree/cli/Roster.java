package org.kdtree.cli;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.kdtree.files.CsvFields;

/**
 * A class's roster, {@code grade-class --roster roster.csv}: a CSV file with the header
 * {@code file,name,id} and one line per student (the jar's file name in the class folder, the
 * student's name, the student's id), which names each row of the table instead of the jar.
 */
final class Roster {
    /** The one header a roster has. */
    static final String HEADER = "file,name,id";

    /** One student: the jar's file name, the name, the id. */
    record Student(String file, String name, String id) {
    }

    private final Map<String, Student> byFile;

    private Roster(Map<String, Student> byFile) {
        this.byFile = byFile;
    }

    /**
     * Reads a roster; a file that is not one is one line naming the file, the line and what is allowed.
     *
     * @param option the option that named it
     * @param file the roster
     * @return the roster
     */
    static Roster read(String option, Path file) {
        String where = option + " " + file;
        if (Files.isDirectory(file)) throw new IllegalArgumentException(where + ": is a folder, not a file");
        List<String> lines;
        try {
            lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IllegalArgumentException(where + (Files.exists(file) ? ": cannot be read (" + e.getMessage() + ")" : ": no such file"));
        }
        if (lines.isEmpty() || !header(lines.get(0)))
            throw new IllegalArgumentException(where + ":1: the first line must be the header " + HEADER + ", got "
                    + (lines.isEmpty() ? "an empty file" : "\"" + StudentRow.shortened(lines.get(0)) + "\""));
        Map<String, Student> byFile = new LinkedHashMap<>();
        Map<String, Integer> lineOf = new LinkedHashMap<>();
        for (int i = 1; i < lines.size(); i++) {
            if (lines.get(i).isBlank()) continue;
            List<String> f = CsvFields.of(lines.get(i));
            String at = where + ":" + (i + 1) + ": ";
            if (f.size() != 3) throw new IllegalArgumentException(at + "a line has 3 fields (" + HEADER + "), this one has " + f.size());
            String jar = f.get(0).strip();
            if (jar.isEmpty()) throw new IllegalArgumentException(at + "the file (the student's jar's name) is empty");
            if (!jar.toLowerCase(Locale.ROOT).endsWith(".jar") || jar.contains("/"))
                throw new IllegalArgumentException(at + "the file must be a jar's name in the class folder, such as alice.jar, got \"" + jar + "\"");
            Integer before = lineOf.putIfAbsent(jar, i + 1);
            if (before != null) throw new IllegalArgumentException(at + jar + " is listed twice (line " + before + " too)");
            byFile.put(jar, new Student(jar, f.get(1).strip(), f.get(2).strip()));
        }
        return new Roster(byFile);
    }

    private static boolean header(String line) {
        List<String> f = CsvFields.of(line.replace("\uFEFF", ""));   // a spreadsheet's byte-order mark
        return f.stream().map(s -> s.strip().toLowerCase(Locale.ROOT)).toList().equals(List.of("file", "name", "id"));
    }

    /** {@return the roster's student of jar file {@code file}, or null} */
    Student of(String file) {
        return byFile.get(file);
    }

    /** {@return the rows named by the roster; a jar it does not list keeps the name it had} */
    List<StudentRow> name(List<StudentRow> rows) {
        List<StudentRow> out = new ArrayList<>();
        for (StudentRow r : rows) {
            Student s = of(r.file());
            out.add(s == null ? r : r.named(s.name().isEmpty() ? r.student() : s.name(), s.id()));
        }
        return out;
    }

    /**
     * What does not match between the roster and the class folder: one line per student with no
     * jar, one per jar with no student.
     *
     * @param jars the jars' file names
     * @return the lines, roster order then folder order
     */
    List<String> mismatches(Collection<String> jars) {
        List<String> lines = new ArrayList<>();
        Set<String> handedIn = Set.copyOf(jars);
        for (Student s : byFile.values())
            if (!handedIn.contains(s.file()))
                lines.add("roster: " + s.name() + (s.id().isEmpty() ? "" : " (" + s.id() + ")") + ": no jar " + s.file() + " in the folder");
        for (String jar : jars)
            if (!byFile.containsKey(jar)) lines.add("roster: " + jar + " is not on the roster: named as before (its manifest, else its file name)");
        return lines;
    }
}
