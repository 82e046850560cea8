package org.kdtree.cli;

import java.io.OutputStream;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import org.kdtree.check.TreeTape;
import org.kdtree.limits.Deadlines;
import org.kdtree.spec.BuilderSpec;
import org.kdtree.spec.Builders;

/**
 * The entry point of a student's JVM ({@link StudentJvm}'s child, in its box): builds, with the
 * student's one builder (or the library's SAH, for the class's reference times), what the grade's
 * checks build, and sends every tree (or fault) down standard output as a {@link TreeTape} for the
 * trusted side to check; prints nothing else there (the builder's own printing goes to standard
 * error). Errors are the command line's one line and exit code ({@link Failure}).
 *
 * <p>Its few arguments are read here, not by picocli: a grade is a short run, and picocli's model
 * of the whole command line (every command's options, found by reflection, in classes too old
 * for class data sharing) cost about a fifth of it.
 *
 * <p>Arguments: {@code --student-jar JAR} or {@code --reference}, then {@code --call-deadline SECONDS
 * --build-deadline SECONDS}.
 */
final class StudentMain {
    private StudentMain() {
    }

    /**
     * Runs the grade's builds and exits with the command line's codes.
     * @param args as {@link StudentJvm} gives them
     */
    public static void main(String[] args) {
        int code;
        try {
            code = run(List.of(args));
        } catch (Exception | Error e) {
            code = Failure.report(e, new PrintWriter(System.err, true));
        }
        System.exit(code);
    }

    private static int run(List<String> args) {
        if (args.size() != 5 && args.size() != 6) throw new IllegalArgumentException("a student's JVM takes --student-jar JAR "
                + "or --reference, then --call-deadline SECONDS --build-deadline SECONDS; got " + args);
        boolean reference = args.get(0).equals("--reference");
        int at = reference ? 1 : 2;
        if (!reference && !args.get(0).equals("--student-jar")) throw new IllegalArgumentException("unknown argument " + args.get(0));
        Deadlines deadlines = new Deadlines(seconds(args, at, "--call-deadline"), seconds(args, at + 2, "--build-deadline"));
        OutputStream channel = System.out; // raw bytes through it; from here on, what anyone prints goes to standard error
        System.setOut(System.err);
        Main.registerTheCourseExample();   // the same builder names as the command line's
        String builder = reference ? "sah" : onlyBuilder(Path.of(args.get(1)));
        BuilderSpec graded = BuilderSpec.of(builder);
        TreeTape.Recorder tape = new TreeTape.Recorder(channel, graded.create());
        new GradeRun(graded::create, tape).run(builder, deadlines, new ProgressBar(null, 1, "checks"));
        tape.end();
        return 0;
    }

    private static double seconds(List<String> args, int at, String option) {
        if (!args.get(at).equals(option)) throw new IllegalArgumentException("expected " + option + ", got " + args.get(at));
        try {
            return Double.parseDouble(args.get(at + 1));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(option + " " + args.get(at + 1) + ": not a number of seconds");
        }
    }

    /** The name of the one builder a student's jar lists; a jar with none or several is refused in one line. */
    private static String onlyBuilder(Path jar) {
        List<String> names = Builders.loadPlugins(jar);
        if (names.size() != 1)
            throw new IllegalArgumentException(jar.getFileName() + " lists " + names.size() + " builders (" + String.join(", ", names)
                    + "); a student's jar lists one");
        return names.get(0);
    }
}
