package org.kdtree.gui;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.kdtree.generate.Shapes;
import org.kdtree.shape.Scene2D;
import org.kdtree.spec.BuilderSpec;

class BackgroundBuildTest {
    /**
     * A superseded build's outcome, caught on the event thread just as a newer build starts, is
     * never shown after the newer one's: the workbench would show the old scene's tree as current.
     */
    @Test void anOlderOutcomeIsNeverDeliveredAfterANewerOne() throws Exception {
        BackgroundBuild builds = new BackgroundBuild("test build");
        Scene2D scene = new Scene2D(Shapes.clustered(50, 3).shapes());
        List<String> shown = new CopyOnWriteArrayList<>();
        CountDownLatch firstInHand = new CountDownLatch(1), letFirstGo = new CountDownLatch(1);
        builds.start(BuilderSpec.of("sah"), scene, false, o -> {
            firstInHand.countDown();
            await(letFirstGo);
            shown.add("first");
        });
        assertThat(firstInHand.await(60, TimeUnit.SECONDS)).as("the first build is delivered on the event thread").isTrue();
        Thread release = new Thread(() -> {
            sleep(300);
            letFirstGo.countDown();
        });
        release.start();
        boolean ended = builds.start(BuilderSpec.of("sah"), scene, true, o -> shown.add("second"));
        release.join();
        javax.swing.SwingUtilities.invokeAndWait(() -> { });
        if (!ended) for (long end = System.nanoTime() + 60_000_000_000L; shown.size() < 2 && System.nanoTime() < end; ) sleep(20);
        assertThat(shown).as("the newest build's outcome is the last one shown").containsExactly("first", "second");
    }

    private static void await(CountDownLatch l) {
        try {
            l.await(60, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
