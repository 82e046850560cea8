package org.kdtree.kdtree;

import static org.junit.jupiter.api.Assumptions.assumeTrue;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.kdtree.generate.Shapes;
import org.kdtree.limits.Deadlines;
import org.kdtree.shape.Scene2D;
import org.kdtree.spec.Builders;
import org.kdtree.testing.InfinitePlaneBuilder;
import org.kdtree.testing.LoopingFindPlaneBuilder;
import org.kdtree.testing.LoopingTerminateBuilder;
import org.kdtree.testing.NaNPlaneBuilder;
import org.kdtree.testing.SleepyBuilder;
import org.kdtree.testing.ThrowingBuilder;

/** A builder that throws, answers wrongly, hangs or crawls is stopped and named; its thread does not stay spinning. */
class SupervisorTest {
    private static final Scene2D SCENE = Shapes.mixed(40, 3);
    private static final Supervisor QUICK = Supervisor.of(new Deadlines(0.5, 1.5));

    @Test void aBuilderThatThrowsIsNamedWithTheMethodAndTheNode() {
        BuilderFault f = catchThrowableOfType(() -> QUICK.build(new ThrowingBuilder(), SCENE), BuilderFault.class);
        assertThat(f.kind()).isEqualTo(BuilderFault.Kind.THREW);
        assertThat(f.getMessage()).matches("builder throws: findPlane threw ArrayIndexOutOfBoundsException "
                + "\\(Index 2 out of bounds for length 2\\) at org\\.kdtree\\.testing\\.ThrowingBuilder\\.findPlane\\(ThrowingBuilder\\.java:\\d+\\), "
                + "at depth 0 on a node of 40 primitives; findPlane must return a plane for every node that terminate does not make a leaf");
    }

    @Test void impossiblePlanesAreBadAnswers() {
        for (KdTreeBuilder b : new KdTreeBuilder[] {new NaNPlaneBuilder(), new InfinitePlaneBuilder()}) {
            BuilderFault f = catchThrowableOfType(() -> QUICK.build(b, SCENE), BuilderFault.class);
            assertThat(f.kind()).as(b.name()).isEqualTo(BuilderFault.Kind.BAD_ANSWER);
            assertThat(f.getMessage()).as(b.name()).startsWith("builder " + b.name() + ": findPlane made an impossible plane (split position must be finite, got ");
        }
    }

    @Test void aCallThatNeverReturnsIsStoppedAndItsThreadEnds() {
        // Stopping a hung builder's thread needs Thread.stop, which JDK 20 removed: CI's JDK 17 run checks it.
        assumeTrue(Runtime.version().feature() < 20, "Thread.stop works up to JDK 19");
        BuilderFault f = catchThrowableOfType(() -> QUICK.build(new LoopingFindPlaneBuilder(), SCENE), BuilderFault.class);
        assertThat(f.getMessage()).isEqualTo("builder loops-in-findplane: findPlane did not return within 0.5 s, at depth 0 on a node of "
                + "40 primitives; it was stopped: look for a loop that never ends in findPlane");
        assertThat(threadsNamed("build by loops-in-findplane")).isZero();

        BuilderFault t = catchThrowableOfType(() -> QUICK.build(new LoopingTerminateBuilder(), SCENE), BuilderFault.class);
        assertThat(t.kind()).isEqualTo(BuilderFault.Kind.HUNG);
        assertThat(t.method()).isEqualTo(BuilderFault.TERMINATE);
        assertThat(threadsNamed("build by loops-in-terminate")).isZero();
    }

    @Test void aBuildWhoseCallsReturnButCrawlIsSlowNotHung() {
        BuilderFault f = catchThrowableOfType(() -> QUICK.build(new SleepyBuilder(), SCENE), BuilderFault.class);
        assertThat(f.kind()).isEqualTo(BuilderFault.Kind.SLOW);
        assertThat(f.getMessage()).matches("builder sleepy: slow: \\d+ ms per node against [0-9.e-]+ ms per node for the library's "
                + "median plane on this scene; stopped after 1\\.\\d s at \\d nodes; look for work repeated on every call "
                + "\\(sorting every primitive, sleeping\\)");
    }

    @Test void interruptingTheCallerCancelsTheBuild() throws Exception {
        // Stopping a hung builder's thread needs Thread.stop, which JDK 20 removed: CI's JDK 17 run checks it.
        assumeTrue(Runtime.version().feature() < 20, "Thread.stop works up to JDK 19");
        AtomicReference<Throwable> outcome = new AtomicReference<>();
        Thread caller = new Thread(() -> {
            try {
                Supervisor.of(Deadlines.GRADE).build(new LoopingFindPlaneBuilder(), SCENE);
            } catch (Throwable e) {
                outcome.set(e);
            }
        });
        caller.start();
        Thread.sleep(300);
        caller.interrupt();
        caller.join(5_000);
        assertThat(outcome.get()).isInstanceOf(CancellationException.class);
        assertThat(threadsNamed("build by loops-in-findplane")).isZero();
    }

    @Test void theLibrarysBuildersAreTrustedOnlyWhenAskedTo() {
        assertThat(Supervisor.isLibrarys(new MedianPlaneBuilder())).isTrue();
        assertThat(Supervisor.isLibrarys(Builders.create("centre-midpoint"))).isTrue();
        assertThat(Supervisor.isLibrarys(new SleepyBuilder())).isFalse();
        assertThat(QUICK.trustingTheLibrary().build(new MedianPlaneBuilder(), SCENE).nodeCount())
                .isEqualTo(new MedianPlaneBuilder().build(SCENE).nodeCount());
        assertThatThrownBy(() -> QUICK.trustingTheLibrary().build(new SleepyBuilder(), SCENE)).isInstanceOf(BuilderFault.class);
    }

    /** Live threads of that name, after giving a stopped one a moment to unwind. */
    private static long threadsNamed(String name) {
        long deadline = System.nanoTime() + 2_000_000_000L;
        long n;
        do {
            n = Thread.getAllStackTraces().keySet().stream().filter(t -> t.getName().equals(name) && t.isAlive()).count();
        } while (n > 0 && System.nanoTime() < deadline && sleep());
        return n;
    }

    private static boolean sleep() {
        try {
            Thread.sleep(20);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return true;
    }
}
