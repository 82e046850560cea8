package org.kdtree.contract;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.lang.reflect.Method;
import java.util.List;
import org.junit.jupiter.api.Named;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.params.ParameterizedTest;
import org.kdtree.check.Contract;
import org.kdtree.check.ContractCase;
import org.kdtree.check.QualityChecks;
import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.KdTreeBuilder;

/**
 * Issue 34, item 10: the starter's stub, run with {@code mvn test}, gets one test per case of the
 * contract (19 in all, as the handout says), each failure naming its case: a parameterized test
 * per case, which surefire counts and names one by one, not a test factory, whose cases surefire
 * folds into one test with "Run 1: ... Run 15:" lines that read like reruns.
 */
class ContractReportsTest {
    /** The starter project's stub: both methods throw "TODO". */
    static final class Stub extends KdTreeBuilder {
        @Override public String name() { return "my-builder"; }
        @Override protected boolean terminate(BuildContext c, BuildNode n) { throw new UnsupportedOperationException("TODO: terminate()"); }
        @Override protected SplitPlane findPlane(BuildContext c, BuildNode n) { throw new UnsupportedOperationException("TODO: findPlane()"); }
    }

    static final class StubContract extends KdTreeBuilderContract {
        @Override protected KdTreeBuilder newBuilder() { return new Stub(); }
    }

    @Test void eachCaseIsATestOfItsOwnNamedAsTheCase() throws Exception {
        List<String> names = KdTreeBuilderContract.cases().map(a -> ((Named<?>) a.get()[0]).getName()).toList();
        assertThat(names).isEqualTo(Contract.cases().stream().map(ContractCase::name).toList()).doesNotHaveDuplicates();
        assertThat(names.size() + 1 + 2).as("cases, the guard, two properties: the handout's count").isEqualTo(19);
        List<String> quality = KdTreeBuilderQualityContract.checks().map(a -> ((Named<?>) a.get()[0]).getName()).toList();
        assertThat(quality).isEqualTo(QualityChecks.cases().stream().map(ContractCase::name).toList());
        for (Class<?> c : List.of(KdTreeBuilderContract.class, KdTreeBuilderQualityContract.class))
            for (Method m : c.getDeclaredMethods())
                assertThat(m.isAnnotationPresent(TestFactory.class)).as(c.getSimpleName() + "." + m.getName() + " is a test factory").isFalse();
        assertThat(KdTreeBuilderContract.class.getDeclaredMethod("contract", ContractCase.class).isAnnotationPresent(ParameterizedTest.class)).isTrue();
    }

    @Test void aFailureStartsWithItsCasesName() {
        ContractCase first = Contract.cases().get(0);
        assertThatThrownBy(() -> new StubContract().contract(first)).isInstanceOf(AssertionError.class)
                .hasMessageStartingWith(first.name() + ": builder my-builder: terminate threw UnsupportedOperationException (TODO: terminate())");
    }
}
