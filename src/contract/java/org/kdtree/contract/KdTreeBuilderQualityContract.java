package org.kdtree.contract;

import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Named;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.kdtree.check.ContractCase;
import org.kdtree.check.QualityChecks;
import org.kdtree.kdtree.KdTreeBuilder;

/**
 * The contract's quality tier, opt-in (graders use it): extend this class as you extend
 * {@link KdTreeBuilderContract}, and JUnit runs {@link QualityChecks}' three checks on the
 * course scenes: no plane separates nothing, leaves stop before the depth cap, and the expected
 * SAH cost is no higher than the median-plane builder's.
 *
 * <pre>
 * class MyBuilderQualityTest extends KdTreeBuilderQualityContract {
 *     &#64;Override protected KdTreeBuilder newBuilder() { return new MyBuilder(); }
 * }
 * </pre>
 */
public abstract class KdTreeBuilderQualityContract {
    /** {@return a new builder with the settings under test} */
    protected abstract KdTreeBuilder newBuilder();

    /** {@return the quality checks, each named} (one test each in surefire's count, as {@link KdTreeBuilderContract}'s cases) */
    static Stream<Arguments> checks() {
        return QualityChecks.cases().stream().map(c -> Arguments.of(Named.of(c.name(), c)));
    }

    /**
     * One quality check; a failure starts with the check's name.
     * @param c the check
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("checks")
    void quality(ContractCase c) {
        try {
            c.run(this::newBuilder);
        } catch (RuntimeException | AssertionError e) {
            throw new AssertionError(c.name() + ": " + e.getMessage(), e);
        }
    }
}
