package org.kdtree.check;

/**
 * A builder broke the contract: the message says, in words a student can act on, which
 * invariant broke and where. An {@link AssertionError}, so that JUnit reports it as a failed
 * test, while the library itself needs no test framework.
 */
public final class ContractViolation extends AssertionError {
    private static final long serialVersionUID = 1L;

    /**
     * A violation with its explanation.
     * @param message what broke, where, and what the builder must do instead
     */
    public ContractViolation(String message) {
        super(message);
    }

    /**
     * A violation found as {@code cause} (a builder's own fault: its message is the explanation).
     * @param message what broke, where, and what the builder must do instead
     * @param cause what was found, for a report that looks further (grade: a hung builder)
     */
    public ContractViolation(String message, Throwable cause) {
        super(message, cause);
    }

    /**
     * Throws a violation unless {@code holds}.
     * @param holds the invariant
     * @param message what broke, if it does not hold
     */
    public static void require(boolean holds, String message) {
        if (!holds) throw new ContractViolation(message);
    }
}
