package org.kdtree.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * How a student's JVM is started. A grade is a short run: about a second of building and
 * checking, in a JVM that would spend more CPU time starting and compiling than that. So the
 * students' JVMs compile with C1 alone ({@code -XX:TieredStopAtLevel=1}: C2's compilations do not
 * pay back in a run this short; measured in docs/write-your-own-builder.md, "How long"), collect
 * with the serial collector (one small heap, no collector threads competing with the other
 * students' JVMs), and, in a class, map the library's classes from an archive made once for the
 * class (class data sharing) instead of reading and verifying them again. The archive is written
 * by a trusted run (the library's SAH graded as a student is, {@link StudentJvm#forClass}) and
 * is read-only in every student's box.
 *
 * <p>C1's code runs a builder's loops slower than C2's would: the build times a student is
 * compared with are the library's SAH's, timed in a JVM started the same way.
 *
 * @param archive  the class's archive of the library's classes, or null for none
 * @param required whether the JVM must map the archive or fail ({@code -Xshare:on}: to try an archive once), rather than
 *                 start without it
 */
record JvmStart(Path archive, boolean required) {
    /** No archive: a grade of one jar, where making one would cost more than it saves. */
    static final JvmStart PLAIN = new JvmStart(null, false);
    /** The archive's file name, in the folder it is made in. */
    static final String FILE = "library.jsa";
    /** Where the archive's folder is inside a box. */
    static final String FOLDER_INSIDE = "/box/cds";

    /**
     * {@return the JVM's options}
     * @param heapMb the heap
     * @param boxed whether the JVM runs in a box (the archive is then at {@value #FOLDER_INSIDE})
     */
    List<String> options(int heapMb, boolean boxed) {
        // the JVM's own warnings (a thread it could not start) go to standard error: standard output is the report channel;
        // and no performance data file (hsperfdata) in the temporary folder, in the box or not
        List<String> o = new ArrayList<>(List.of("-Xmx" + heapMb + "m", "-Djava.awt.headless=true", "-Xlog:disable",
                "-Xlog:all=warning:stderr", "-XX:-UsePerfData", "-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC"));
        if (archive != null) o.add("-XX:SharedArchiveFile=" + (boxed ? FOLDER_INSIDE + "/" + FILE : archive.toString()));
        if (archive != null && required) o.add("-Xshare:on");
        return o;
    }

    /** {@return how the students' JVMs start, in words, for the class's summary line} */
    String describe() {
        return "the students' JVMs: C1 compiler only, serial collector, "
                + (archive == null ? "the library's classes read by each" : "the library's classes mapped from an archive made for the class");
    }

    /** {@return the box's binds for the archive: read-only} */
    List<String> binds() {
        // its folder made first, readable by the box's user (a folder bubblewrap makes for a file is not)
        return archive == null ? List.of() : List.of("--perms", "0755", "--dir", FOLDER_INSIDE, "--ro-bind", archive.toString(), FOLDER_INSIDE + "/" + FILE);
    }

    /**
     * {@return the options of the trusted run that makes the archive in {@code folder}}
     * @param folder where the archive is written (writable by the box's user)
     * @param boxed whether that run is in a box
     */
    static List<String> dump(Path folder, boolean boxed) {
        return List.of("-XX:ArchiveClassesAtExit=" + (boxed ? FOLDER_INSIDE + "/" + FILE : folder.resolve(FILE).toString()));
    }

    /** {@return the box's binds of the run that makes the archive: its folder writable} */
    static List<String> dumpBinds(Path folder) {
        return List.of("--bind", folder.toString(), FOLDER_INSIDE);
    }
}
