package org.kdtree.cli;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/** {@code --rubric} and {@code --junit-xml}, the options by which {@code grade} and {@code grade-class} score (a picocli mixin). */
final class ScoringOptions {
    @Option(names = "--rubric", paramLabel = "FILE", description = "Points and visibility per check (JSON: see the handout); "
            + "adds the score to the report. Without it the verdict stands alone (and JUnit XML and Gradescope's results "
            + "give each pass/fail check one point).")
    Path rubric;

    @Option(names = "--junit-xml", paramLabel = "FILE", description = "Also write the grades as JUnit XML: one test case per "
            + "check per student, a failure for each check lost, with the student's fault.")
    Path junitXml;

    /** {@return the rubric given, or null} refused in one line naming the file and field, before any grading */
    Rubric read() {
        return rubric == null ? null : Rubric.read("--rubric", rubric);
    }

    /** {@return the rubric given, else one point for each pass/fail check} */
    static Rubric orOnePointEach(Rubric given) {
        return given != null ? given : Rubric.onePointEach();
    }
}
