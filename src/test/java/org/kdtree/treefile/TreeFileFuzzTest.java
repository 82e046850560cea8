package org.kdtree.treefile;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.Hit;
import org.kdtree.accel.RayQuery;
import org.kdtree.geom.Ray;

/**
 * Issue 43, item 4: mutated files, a bounded number of tries in the normal suite. A file with a
 * few bytes changed, cut or grown is refused in one line ({@link TreeFileException}), never
 * loaded; with its checksum made to match again (damage on purpose), it is refused in one line or
 * loads a tree whose queries run: no other exception, no hang, whatever the bytes.
 */
class TreeFileFuzzTest {
    private static final byte[][] FILES = {BadTreeFilesTest.kdFile(), BadTreeFilesTest.bvhFile()};

    /** {@code file} with {@code changes} bytes set at positions and to values drawn from {@code seed}, then cut or grown by {@code resize}. */
    private static byte[] mutated(byte[] file, long seed, int changes, int resize) {
        java.util.Random rnd = new java.util.Random(seed);
        byte[] bad = Arrays.copyOf(file, Math.max(0, file.length + resize));
        for (int i = 0; i < changes && bad.length > 0; i++) {
            int at = rnd.nextInt(bad.length);
            byte b = (byte) rnd.nextInt(256);
            bad[at] = b == bad[at] ? (byte) ~b : b;
        }
        if (Arrays.equals(bad, file)) bad[(int) Math.floorMod(seed, (long) bad.length)] ^= 1;   // two changes undid each other
        return bad;
    }

    @Property(tries = 400)
    void aDamagedFileIsAlwaysRefused(@ForAll @IntRange(min = 0, max = 1) int which, @ForAll long seed,
                                     @ForAll @IntRange(min = 1, max = 8) int changes, @ForAll @IntRange(min = -8, max = 8) int resize) {
        byte[] bad = mutated(FILES[which], seed, changes, resize);
        BadTreeFilesTest.refusal(bad, BadTreeFilesTest.MESH);
    }

    @Property(tries = 400)
    void aForgedFileIsRefusedInOneLineOrAnswers(@ForAll @IntRange(min = 0, max = 1) int which, @ForAll long seed,
                                                @ForAll @IntRange(min = 1, max = 4) int changes) {
        byte[] file = FILES[which];
        java.util.Random rnd = new java.util.Random(seed);
        byte[] bad = file.clone();
        for (int i = 0; i < changes; i++) {   // past the prefix, before the checksum: the magic, version and length have their own tests
            int at = TreeFormat.PREFIX + rnd.nextInt(file.length - TreeFormat.PREFIX - 4);
            bad[at] = (byte) rnd.nextInt(256);
        }
        SavedTree loaded;
        try {
            loaded = Saved.read(BadTreeFilesTest.forged(bad), BadTreeFilesTest.MESH);
        } catch (TreeFileException e) {
            assertThat(e.getMessage()).startsWith("test.kdtree: ").doesNotContain("\n");
            return;
        } catch (java.io.IOException e) {
            throw new AssertionError(e);
        }
        traceSome(loaded.structure());
    }

    /** Rays through the scene, through a tree that loaded: they must come back, whatever they hit. */
    private static void traceSome(AccelerationStructure tree) {
        RayQuery q = tree.query(), listened = tree.query(org.kdtree.accel.TraversalListener.NONE);
        Ray ray = new Ray(3);
        Hit hit = new Hit();
        java.util.Random rnd = new java.util.Random(1);
        for (int i = 0; i < 200; i++) {
            ray.set(rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble(), rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
            q.closestHit(ray, 0, Double.POSITIVE_INFINITY, hit);
            listened.closestHit(ray, 0, Double.POSITIVE_INFINITY, hit);
            q.anyHit(ray, 0, Double.POSITIVE_INFINITY);
        }
        tree.stats();
    }
}
