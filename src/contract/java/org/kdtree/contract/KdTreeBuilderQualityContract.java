package org.kdtree.contract;

import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
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

    /** {@return one test per quality check} */
    @TestFactory
    Stream<DynamicTest> quality() {
        return QualityChecks.cases().stream().map(c -> DynamicTest.dynamicTest(c.name(), () -> c.run(this::newBuilder)));
    }
}
