package org.kdtree.cli;

import java.nio.file.Path;
import org.kdtree.tradeoff.ChartFile;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

/**
 * The {@code --csv} and {@code --chart} options of the studies ({@code tradeoff},
 * {@code knn-study}; a picocli mixin): a study's table and its chart (PNG, or SVG by the name),
 * named by default after the command and the data ({@code tradeoff-bunny.csv}), both checked
 * before any work. The options are added in code ({@link AddedOptions}), their help naming the command.
 */
@Command(modelTransformer = AddedOptions.Transformer.class)
final class StudyOutputs implements AddedOptions {
    /** How the help names the data in the default file names, e.g. "MESHNAME". */
    private final String dataLabel;
    private String command;
    private Path csv, chart;

    /** @param dataLabel how the help names the data in the default file names, e.g. "MESHNAME" */
    StudyOutputs(String dataLabel) {
        this.dataLabel = dataLabel;
    }

    /**
     * {@return the CSV file}: the one given, else {@code COMMAND-DATA.csv}
     *
     * @param data the data's name in file names
     */
    Path csv(String data) {
        return csv != null ? csv : Path.of(command + "-" + data + ".csv");
    }

    /**
     * {@return the chart file}: the one given, else {@code COMMAND-DATA.png}
     *
     * @param data the data's name in file names
     */
    Path chart(String data) {
        return chart != null ? chart : Path.of(command + "-" + data + ".png");
    }

    /**
     * Refuses, before any work, an output that cannot be written, one that is an input of the
     * study, and a chart of a format not drawn.
     *
     * @param data          the data's name in file names
     * @param namesAndFiles the study's input files, each after its name as its help gives it
     *                      ("MESH", mesh, ...); a null file is left out
     */
    void check(String data, Object... namesAndFiles) {
        Path csvFile = csv(data), chartFile = chart(data);
        CommandFiles.requireWritable("--csv", csvFile);
        CommandFiles.requireWritable("--chart", chartFile);
        requireNotInput("--csv", csvFile, namesAndFiles);
        requireNotInput("--chart", chartFile, namesAndFiles);
        ChartFile.requireFormat("--chart", chartFile);
    }

    private static void requireNotInput(String option, Path out, Object... namesAndFiles) {
        for (int i = 0; i + 1 < namesAndFiles.length; i += 2)
            CommandFiles.requireNotInput(option, out, (String) namesAndFiles[i], (Path) namesAndFiles[i + 1]);
    }

    /** Adds {@code --csv} and {@code --chart} to the command that mixes them in, their help naming it. */
    @Override public void addTo(CommandSpec command) {
        this.command = command.name();
        String name = this.command + "-" + dataLabel;
        command.addOption(OptionSpec.builder("--csv").type(Path.class).paramLabel("FILE")
                .description("CSV output file (default: " + name + ".csv).").setter(AddedOptions.setter(v -> csv = (Path) v)).build());
        command.addOption(OptionSpec.builder("--chart").type(Path.class).paramLabel("FILE")
                .description("Chart file, .png or .svg (default: " + name + ".png).").setter(AddedOptions.setter(v -> chart = (Path) v))
                .build());
    }
}
