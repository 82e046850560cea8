package org.kdtree.measure;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.kdtree.geom.Box;

/** The spec's ray sets and their random generator, value for value. */
class RaySetTest {
    @Test void splitMix64MatchesTheReferenceValues() {
        SplitMix64 zero = new SplitMix64(0);
        assertThat(zero.nextLong()).isEqualTo(0xE220A8397B1DCDAFL);
        assertThat(zero.nextLong()).isEqualTo(0x6E789E6AA1B965F4L);
        SplitMix64 r = new SplitMix64(42);
        assertThat(r.nextLong()).isEqualTo(0xBDD732262FEB6E95L);
        assertThat(r.nextLong()).isEqualTo(0x28EFE333B266F103L);
        assertThat(r.nextLong()).isEqualTo(0x47526757130F9F52L);
        assertThat(new SplitMix64(42).nextDouble()).isEqualTo((0xBDD732262FEB6E95L >>> 11) * 0x1.0p-53);
    }

    @Test void specRaySets() {
        Box box = Box.of3(-1, 0, 2, 3, 2, 6);
        RaySet r = RaySet.random(box, RaySet.SPEC_RANDOM_RAYS);
        assertThat(r.size()).isEqualTo(1_000_000);
        SplitMix64 rng = new SplitMix64(42);
        double ux = rng.nextDouble(), uy = rng.nextDouble(), uz = rng.nextDouble(), u = rng.nextDouble(), v = rng.nextDouble();
        assertThat(r.rays()[0]).isEqualTo(-1 + ux * 4);
        assertThat(r.rays()[1]).isEqualTo(0 + uy * 2);
        assertThat(r.rays()[2]).isEqualTo(2 + uz * 4);
        double zc = 1 - 2 * u, rr = Math.sqrt(Math.max(0, 1 - zc * zc));
        assertThat(r.rays()[3]).isEqualTo(rr * Math.cos(2 * Math.PI * v));
        assertThat(r.rays()[5]).isEqualTo(zc);

        RaySet p = RaySet.primary(box, RaySet.SPEC_IMAGE);
        double[] pr = p.rays();
        assertThat(p.size()).isEqualTo(1024 * 1024);
        double d = Math.sqrt(16 + 4 + 16), wl = Math.sqrt(1 + 0.25 + 4);
        assertThat(pr[0]).isEqualTo(1 + 1.5 * d * (1 / wl));
        assertThat(pr[1]).isEqualTo(1 + 1.5 * d * (0.5 / wl));
        // The four centre pixels look (almost) straight at the centre c = (1, 1, 4).
        int centre = 6 * (512 * 1024 + 512) + 3;
        double[] toC = {1 - pr[0], 1 - pr[1], 4 - pr[2]};
        double len = Math.sqrt(toC[0] * toC[0] + toC[1] * toC[1] + toC[2] * toC[2]), dot = 0;
        for (int a = 0; a < 3; a++) dot += toC[a] / len * pr[centre + a];
        assertThat(dot).isGreaterThan(0.99999);
        // Pixel (0, 0) is top left: up and to the left of forward.
        assertThat(pr[4]).isGreaterThan(pr[6 * (1024 * 1023 + 1023) + 4]);
        assertThat(String.format(Locale.ROOT, "%.1f", pr[3] * pr[3] + pr[4] * pr[4]
                + pr[5] * pr[5])).isEqualTo("1.0");
    }
}
