package org.kdtree.cli;

import org.kdtree.generate.MeshGrid;
import org.kdtree.limits.Limits;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.TriangleMesh;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;

/**
 * The {@code --grid N} option of the commands that read a mesh (a picocli mixin): the mesh
 * repeated in an N x N grid on the x-z plane ({@link MeshGrid}), the benchmark's scaling scene
 * at 4. The range and the grid are the same everywhere; each command words the help, so the
 * option is added in code ({@link AddedOptions}).
 */
@Command(modelTransformer = AddedOptions.Transformer.class)
final class GridOption implements AddedOptions {
    private final String help;
    private int n = 1;

    /** @param help the option's help in the command */
    GridOption(String help) {
        this.help = help;
    }

    /** {@return what the mesh's name is followed by in reports and file names: "-grid4" for a grid of 4 x 4, nothing for none} */
    String suffix() {
        return n > 1 ? "-grid" + n : "";
    }

    /** Refuses an N outside {@code Limits.GRID}, naming the option. */
    void check() {
        Limits.GRID.check("--grid", n);
    }

    /**
     * {@return {@code mesh} in the grid} (itself for N = 1)
     *
     * @param mesh the mesh read
     */
    TriangleMesh of(TriangleMesh mesh) {
        return MeshGrid.grid(mesh, n);
    }

    /**
     * {@return {@code scene} in the grid} (itself for N = 1)
     *
     * @param scene the scene read, of any kind
     * @throws IllegalArgumentException for a grid of anything but a mesh
     */
    Primitives of(Primitives scene) {
        if (n == 1) return scene;
        if (!(scene instanceof TriangleMesh mesh)) throw new IllegalArgumentException("--grid applies to OBJ meshes only");
        return of(mesh);
    }

    /** Adds {@code --grid} to the command that mixes it in. */
    @Override public void addTo(CommandSpec command) {
        command.addOption(OptionSpec.builder("--grid").type(int.class).paramLabel("N").defaultValue("1").description(help)
                .setter(AddedOptions.setter(v -> n = v == null ? 1 : (Integer) v)).build());
    }
}
