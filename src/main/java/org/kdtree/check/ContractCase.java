package org.kdtree.check;

import java.util.function.Supplier;
import org.kdtree.kdtree.KdTreeBuilder;

/**
 * One named check of the builder contract: it builds one or more scenes with new builders and
 * throws {@link ContractViolation} (or the builder's own exception) when the builder breaks it.
 *
 * @param name what is checked, as a test report or the grading table shows it
 * @param check runs the check on builders made by the supplier
 */
public record ContractCase(String name, Check check) {
    /** The body of a case. */
    @FunctionalInterface
    public interface Check {
        /**
         * Runs the check.
         * @param builders makes a new builder with the settings under test
         */
        void run(Supplier<? extends KdTreeBuilder> builders);
    }

    /**
     * Runs the check.
     * @param builders makes a new builder with the settings under test
     */
    public void run(Supplier<? extends KdTreeBuilder> builders) {
        check.run(builders);
    }

    @Override public String toString() { return name; }
}
