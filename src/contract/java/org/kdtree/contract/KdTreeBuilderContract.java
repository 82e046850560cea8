package org.kdtree.contract;

import java.util.Map;
import java.util.ServiceLoader;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.lifecycle.AfterContainer;
import org.junit.jupiter.api.Named;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.platform.engine.TestEngine;
import org.kdtree.check.Contract;
import org.kdtree.check.ContractCase;
import org.kdtree.check.ContractViolation;
import org.kdtree.kdtree.BuilderFault;
import org.kdtree.kdtree.KdTreeBuilder;

/**
 * The contract every {@link KdTreeBuilder} must honour: extend this class, implement
 * {@link #newBuilder()}, and JUnit runs every case of {@link Contract} on 2-D and 3-D scenes,
 * the hard inputs included, and jqwik two properties on random scenes. A failure says, in
 * words, which invariant broke and where.
 *
 * <pre>
 * class MyBuilderTest extends KdTreeBuilderContract {
 *     &#64;Override protected KdTreeBuilder newBuilder() { return new MyBuilder(); }
 * }
 * </pre>
 *
 * A run without jqwik's engine would skip the two properties without a word; the test
 * {@code propertyEngineIsPresent} fails it instead.
 *
 * <p>A builder that hangs (a call of {@code terminate} or {@code findPlane} that does not return
 * within its deadline) or crawls fails the check where it did so, once; every check after it, in
 * the same run, fails at once pointing at that one, instead of waiting out a deadline of its own.
 */
public abstract class KdTreeBuilderContract {
    private static final AtomicInteger TRIES = new AtomicInteger();

    /** Per builder class, the first hang or crawl found in this run, and where: the checks after it are not run. */
    private static final Map<Class<?>, String> HALTED = new ConcurrentHashMap<>();

    /** {@return a new builder with the settings under test} */
    protected abstract KdTreeBuilder newBuilder();

    /**
     * {@return the contract's cases, each named} A parameterized test rather than a test factory:
     * Maven's surefire counts and reports each case as a test of its own (a factory's cases are
     * one test to it, whose failures read "Run 1: ... Run 15:" like reruns).
     */
    static Stream<Arguments> cases() {
        return Contract.cases().stream().map(c -> Arguments.of(Named.of(c.name(), c)));
    }

    /**
     * One case of the contract; a failure starts with the case's name, so that every report names it.
     * @param c the case
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void contract(ContractCase c) {
        try {
            guarded(c.name(), () -> c.run(this::newBuilder));
        } catch (RuntimeException | AssertionError e) {
            throw new AssertionError(c.name() + ": " + e.getMessage(), e);
        }
    }

    /** The two properties below run only if jqwik's engine is on the test class path: fail, not skip, if it is not. */
    @Test
    void propertyEngineIsPresent() {
        boolean jqwik = ServiceLoader.load(TestEngine.class).stream().anyMatch(p -> p.type().getName().startsWith("net.jqwik."));
        ContractViolation.require(jqwik, "jqwik's test engine is not on the test class path, so the contract's two property"
                + " tests would be skipped without a word; depend on org.kdtree:kdtree-contract (it brings jqwik along),"
                + " or add net.jqwik:jqwik with <scope>test</scope>.");
    }

    /**
     * Any random 2-D scene of up to 60 shapes.
     * @param n the number of shapes
     * @param seed the scene's seed
     */
    @Property(tries = Contract.RANDOM_2D_TRIES)
    void anyRandom2DScene(@ForAll @IntRange(min = 0, max = 60) int n, @ForAll long seed) {
        TRIES.incrementAndGet();
        guarded("any random 2-D scene", () -> Contract.anyRandom2DScene(newBuilder(), n, seed));
    }

    /**
     * Any soup of up to 80 random triangles.
     * @param n the number of triangles
     * @param seed the scene's seed
     */
    @Property(tries = Contract.RANDOM_TRIANGLE_TRIES)
    void anyRandomTriangleSoup(@ForAll @IntRange(min = 0, max = 80) int n, @ForAll long seed) {
        TRIES.incrementAndGet();
        guarded("any random triangle soup", () -> Contract.anyRandomTriangleSoup(newBuilder(), n, seed));
    }

    /**
     * Runs one check of the builder, unless it already hung or crawled in this run: then it fails
     * at once, naming that finding; a hang or crawl found here is remembered for the checks after.
     */
    private void guarded(String check, Runnable run) {
        Class<?> type = newBuilder().getClass();
        String earlier = HALTED.get(type);
        if (earlier != null) throw new ContractViolation("not run: " + earlier);
        try {
            run.run();
        } catch (RuntimeException | AssertionError e) {
            for (Throwable t = e; t != null; t = t.getCause())
                if (t instanceof BuilderFault f && (f.kind() == BuilderFault.Kind.HUNG || f.kind() == BuilderFault.Kind.SLOW))
                    HALTED.putIfAbsent(type, "builder " + f.builder() + (f.kind() == BuilderFault.Kind.HUNG
                            ? " hung in " + f.method() : " is too slow") + " (see the check '" + check + "')");
            throw e;
        }
    }

    /** Says how many property tries ran, so that a run whose properties were skipped shows it. */
    @AfterContainer
    static void reportTries() {
        System.out.println("kdtree contract: " + TRIES.getAndSet(0) + " property tries executed");
    }
}
