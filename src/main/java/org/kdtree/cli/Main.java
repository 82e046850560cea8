package org.kdtree.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.kdtree.examples.CentreMidpointBuilder;
import org.kdtree.spec.Builders;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine;

/** The command line: {@code java -jar kdtree.jar COMMAND ...}. */
@Command(name = "kdtree", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = "k-d trees for ray tracing: build, inspect, trace, render; nearest neighbours of points.",
        subcommands = {GuiCommand.class, StatsCommand.class, RaycastCommand.class, RenderCommand.class, TradeoffCommand.class,
                KnnCommand.class, KnnStudyCommand.class, CompareTreesCommand.class, SimilarCommand.class, GradeCommand.class,
                ClassGradeCommand.class},
        footer = {"", "Exit codes: 0 done; 1 grade: the builder breaks the contract;",
                "2 a mistake in the command or a file; 3 out of memory;",
                "4 a builder's own fault (a plug-in's: it threw, answered with an impossible",
                "  plane, hung or was slow: the line names it, the method and the node);",
                "70 a bug of ours (a report file is named)."})
public final class Main implements java.util.concurrent.Callable<Integer> {
    /** Read before picocli parses (see {@link #loadPlugins}); declared here for the usage text. */
    @Option(names = "--plugin", paramLabel = "JAR|FOLDER",
            description = "Load the builders a jar (or every jar in a folder) lists in META-INF/services; "
                    + "any command, anywhere on the line, repeatable.")
    List<Path> plugins;

    /** The version the build wrote (the pom's, e.g. 0.1.0-SNAPSHOT), from {@code version.properties}. */
    static final class Version implements CommandLine.IVersionProvider {
        @Override public String[] getVersion() throws java.io.IOException {
            java.util.Properties p = new java.util.Properties();
            try (var in = Main.class.getResourceAsStream("version.properties")) {
                if (in != null) p.load(in);
            }
            return new String[] {"kdtree " + p.getProperty("version", "(version unknown: not built by Maven)")};
        }
    }

    /**
     * Offers the course's worked example ({@code -b centre-midpoint}, {@code grade}, the workbench,
     * the trade-off study) here, in the application, rather than in the library's services file: a
     * library user's {@code Builders.names()} lists the library's builders and plug-ins only.
     */
    static void registerTheCourseExample() {
        Builders.register(new CentreMidpointBuilder().name(), CentreMidpointBuilder::new);
    }

    /**
     * Runs the command line and exits with its code, unless it opened the workbench and succeeded
     * (then the window keeps the JVM running).
     *
     * @param args the command and its options
     */
    public static void main(String[] args) {
        int code = run(args);
        if (code != 0 || !GuiCommand.opened()) System.exit(code); // the workbench's window keeps the JVM alive
    }

    /**
     * Runs the command line and returns the exit code (for tests).
     *
     * @param args the command and its options
     * @return the exit code: 0 on success, nonzero on failure
     */
    public static int run(String... args) {
        registerTheCourseExample();
        try {
            args = loadPlugins(args);
        } catch (RuntimeException e) {
            return Failure.report(e, new CommandLine(new Main()).getErr());
        }
        CommandLine cl = new CommandLine(new Main());   // after the plug-ins: their settings' rows are options too
        cl.setCaseInsensitiveEnumValuesAllowed(true);
        for (CommandLine sub : cl.getSubcommands().values()) sub.getCommandSpec().versionProvider(new Version()); // every -V: the build's
        if (args.length > 0 && !args[0].startsWith("-") && !cl.getSubcommands().containsKey(args[0])) {
            // picocli would print the top-level help for "nearest --help" and exit 0
            cl.getErr().println("error: unknown command '" + args[0] + "'; the commands are "
                    + String.join(", ", cl.getSubcommands().keySet()) + " (kdtree --help)");
            return Failure.USAGE;
        }
        cl.setExecutionExceptionHandler((ex, cmd, parsed) -> Failure.report(ex, cmd.getErr()));
        cl.setParameterExceptionHandler((ex, args1) -> {   // a bad option: one line and where to read more, not the whole usage
            CommandLine cmd = ex.getCommandLine();
            cmd.getErr().println("error: " + ex.getMessage() + " (" + cmd.getCommandSpec().qualifiedName() + " --help)");
            return Failure.USAGE;
        });
        try {
            return cl.execute(args);
        } catch (RuntimeException | Error e) {   // what picocli lets through: errors, failures outside a command
            return Failure.report(e, cl.getErr());
        }
    }

    /**
     * Loads every {@code --plugin JAR|FOLDER} (or {@code --plugin=...}) wherever it stands, so
     * that the builders it adds are known to every command's options and to the workbench, and
     * returns the other arguments.
     */
    private static String[] loadPlugins(String[] args) {
        List<String> rest = new ArrayList<>();
        java.util.Map<String, Path> seen = new java.util.HashMap<>();
        for (int i = 0; i < args.length; i++) {
            if (args[i].equals("--plugin")) {
                if (i + 1 == args.length) throw new IllegalArgumentException("--plugin needs a jar or a folder of jars");
                plugin(Path.of(args[++i]), seen);
            } else if (args[i].startsWith("--plugin=")) {
                plugin(Path.of(args[i].substring("--plugin=".length())), seen);
            } else {
                rest.add(args[i]);
            }
        }
        return rest.toArray(String[]::new);
    }

    /** Loads one {@code --plugin}: the library's line names the jar or folder, the user's line the option too. */
    private static void plugin(Path p, java.util.Map<String, Path> seen) {
        List<String> names;
        try {
            names = Builders.loadPlugins(p);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("--plugin " + e.getMessage(), e);
        }
        try {
            Builders.requireDistinct(p, names, seen);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("--plugin: " + e.getMessage(), e);
        }
    }

    /**
     * No command: open the workbench; where there is no display, print the usage and end with
     * exit code 2, as {@code gui} does (the workbench was asked for and could not open).
     */
    @Override public Integer call() {
        if (java.awt.GraphicsEnvironment.isHeadless()) {
            new CommandLine(this).usage(System.out);
            System.err.println("error: no display for the workbench, the default command (set DISPLAY, or give a command such as 'stats')");
            return Failure.USAGE;
        }
        return new GuiCommand().call();
    }
}
