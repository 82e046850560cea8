package org.kdtree.traverse;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.kdtree.geom.Ray;
import org.kdtree.shape.TriangleMesh;

class SmokeTest {
    @Test void randomRaysInSoupAgreeWithBruteForce() {
        TriangleMesh mesh = Scenes.soup(1, 300, 0.2);
        Random rnd = new Random(2);
        Ray ray = new Ray(3);
        int hits = 0;
        for (Oracle o : Oracle.allBuilders(mesh, new TriangleIntersector(mesh))) {
            for (int i = 0; i < 2000; i++) {
                ray.set(rnd.nextDouble() * 2 - .5, rnd.nextDouble() * 2 - .5, rnd.nextDouble() * 2 - .5,
                        rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
                if (o.check(ray)) hits++;
            }
        }
        assertThat(hits).isGreaterThan(300);
    }
}
