package org.kdtree.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/** The command line: {@code java -jar kdtree.jar COMMAND ...}. */
@Command(name = "kdtree", mixinStandardHelpOptions = true, version = "kdtree 0.1",
        description = "k-d trees for ray tracing: build, inspect, trace, render; nearest neighbours of points.",
        subcommands = {GuiCommand.class, StatsCommand.class, RaycastCommand.class, RenderCommand.class, TradeoffCommand.class,
                KnnCommand.class, KnnStudyCommand.class})
public final class Main implements Runnable {
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
        CommandLine cl = new CommandLine(new Main());
        cl.setCaseInsensitiveEnumValuesAllowed(true);
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

    /** No command: open the workbench, or print the usage where there is no display. */
    @Override public void run() {
        if (java.awt.GraphicsEnvironment.isHeadless()) {
            new CommandLine(this).usage(System.out);
            System.err.println("(no display: the workbench, the default command, needs one)");
        } else {
            new GuiCommand().call();
        }
    }
}
