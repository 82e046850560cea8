package org.kdtree.cli;

import java.util.function.Consumer;
import java.util.stream.Stream;
import picocli.CommandLine.IModelTransformer;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.ISetter;

/**
 * A picocli mixin that adds its options in code, where their help is made at run time
 * ({@link BuilderOptions}, from the settings' rows) or worded by each command ({@link GridOption},
 * {@link StudyOutputs}). Such a mixin is annotated {@code @Command(modelTransformer =
 * AddedOptions.Transformer.class)}: picocli keeps one model transformer per command, so the one
 * transformer adds the options of every such mixin the command has.
 */
interface AddedOptions {
    /**
     * Adds the mixin's options to {@code command}, their values set on the mixin.
     *
     * @param command the command that mixes it in
     */
    void addTo(CommandSpec command);

    /**
     * {@return a setter that passes an option's value to {@code set}}
     *
     * @param set takes the value picocli converted (null for an option's initial value where it has none)
     */
    static ISetter setter(Consumer<Object> set) {
        return new ISetter() {
            @Override public <T> T set(T value) {
                set.accept(value);
                return null;
            }
        };
    }

    /** Adds the options of every {@link AddedOptions} mixin of the command, directly or through a mixin of mixins. */
    final class Transformer implements IModelTransformer {
        @Override public CommandSpec transform(CommandSpec command) {
            mixedIn(command).filter(AddedOptions.class::isInstance).map(AddedOptions.class::cast).forEach(m -> m.addTo(command));
            return command;
        }

        /** The mixins of {@code spec} and theirs. */
        private static Stream<Object> mixedIn(CommandSpec spec) {
            return spec.mixins().values().stream().flatMap(m -> Stream.concat(Stream.of(m.userObject()), mixedIn(m)));
        }
    }
}
