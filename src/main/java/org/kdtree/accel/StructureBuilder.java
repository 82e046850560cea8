package org.kdtree.accel;

import java.util.List;
import org.kdtree.shape.Primitives;

/**
 * What every structure's builder is, to those who pick one by name (the command line, the
 * workbench, the studies): a name, the setting rows it takes, its settings as one value, and a
 * build. The kd-tree's builders and the bounding volume hierarchy's implement it alike, and a
 * plug-in's builder may declare rows of its own (docs/write-your-own-builder.md).
 */
public interface StructureBuilder {
    /** {@return the name it is known by}, e.g. "sah", "bvh" */
    String name();

    /** {@return the setting rows it takes}: the shared ones it reads and its own, in the order help lists them */
    List<Setting<?>> settingRows();

    /** {@return its settings}: every row reads as given there, or as the row's default */
    Settings settings();

    /**
     * Gives it {@code settings}, replacing the ones it had.
     *
     * @param settings the settings; each given row must be one of {@link #settingRows()}
     * @return this builder
     * @throws IllegalArgumentException naming every given row it does not take
     */
    StructureBuilder configure(Settings settings);

    /**
     * Builds the structure of {@code primitives}.
     *
     * @param primitives the scene's primitives
     * @return the structure
     */
    AccelerationStructure build(Primitives primitives);

    /**
     * {@return the depth cap a build over {@code primitives} primitives uses}: Kmaxdepth if given,
     * else the structure's automatic cap
     *
     * @param primitives N
     */
    int depthCap(int primitives);

    /** {@return its settings in one line}, e.g. for the command line */
    String describeSettings();

    /**
     * {@return {@code settings}, checked to give only rows that {@code builder} takes}
     *
     * @param builder  the builder
     * @param settings the settings it is to take
     * @throws Setting.Refused naming the rows it does not take, and the builder
     */
    static Settings checkTakes(StructureBuilder builder, Settings settings) {
        List<Setting<?>> rows = builder.settingRows();
        List<Setting<?>> foreign = settings.givenRows().stream().filter(r -> !rows.contains(r)).toList();
        if (!foreign.isEmpty())
            throw new Setting.Refused(foreign, naming -> foreign.stream().map(naming).collect(java.util.stream.Collectors.joining(", "))
                    + (foreign.size() > 1 ? " do" : " does") + " not apply to the " + builder.name() + " builder");
        return settings;
    }
}
