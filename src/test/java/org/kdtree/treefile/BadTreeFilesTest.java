package org.kdtree.treefile;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.zip.CRC32C;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.kdtree.generate.Meshes;
import org.kdtree.io.PrimitivesReader;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.TriangleMesh;
import org.kdtree.spec.BuilderSpec;

/**
 * Issue 43, item 4: every bad file gets one line naming the file and what is wrong, and nothing
 * else: truncated, a byte flipped anywhere, another magic or version, a stated size beyond the
 * limit, links out of range (in a file whose checksum was made to match), a scene given for a
 * tree and a tree for a scene.
 */
class BadTreeFilesTest {
    static final TriangleMesh MESH = Meshes.clustered(300, 5);

    static byte[] kdFile() {
        BuilderSpec spec = BuilderSpec.of("sah");
        return Saved.bytes(spec.build(MESH, null), spec, MESH);
    }

    static byte[] bvhFile() {
        BuilderSpec spec = BuilderSpec.of("bvh");
        return Saved.bytes(spec.build(MESH, null), spec, MESH);
    }

    /** {@return the refusal's message, after checking it is one line naming the stream} */
    static String refusal(byte[] file, Primitives primitives) {
        Throwable t = org.assertj.core.api.Assertions.catchThrowable(() -> Saved.read(file, primitives));
        assertThat(t).isInstanceOf(TreeFileException.class);
        assertThat(t.getMessage()).startsWith("test.kdtree: ").doesNotContain("\n");
        return t.getMessage();
    }

    /** {@code file} with its checksum made to match its bytes again: damage no checksum sees. */
    static byte[] forged(byte[] file) {
        CRC32C crc = new CRC32C();
        crc.update(file, 0, file.length - 4);
        ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN).putInt(file.length - 4, (int) crc.getValue());
        return file;
    }

    @Test void aTruncatedFileIsRefusedAtEveryLength() {
        byte[] file = kdFile();
        for (int n = 0; n < file.length; n++)
            assertThat(refusal(Arrays.copyOf(file, n), MESH)).as("cut to %d bytes", n).contains("truncated");
        assertThat(refusal(Arrays.copyOf(file, 40), MESH)).isEqualTo("test.kdtree: truncated: 40 bytes of the " + file.length
                + " a tree file needs");
    }

    @Test void aFileCutShortOnDiskIsRefusedBeforeItIsRead(@TempDir Path dir) throws Exception {
        Path f = dir.resolve("cut.kdtree");
        byte[] file = kdFile();
        Files.write(f, Arrays.copyOf(file, file.length - 100));
        assertThatThrownBy(() -> TreeFile.load(f, MESH)).isInstanceOf(TreeFileException.class)
                .hasMessage(f + ": truncated: " + (file.length - 100) + " bytes of the " + file.length + " a tree file needs");
        assertThatThrownBy(() -> TreeFile.load(dir.resolve("none.kdtree"), MESH)).hasMessageEndingWith("none.kdtree: no such file");
        assertThatThrownBy(() -> TreeFile.load(dir, MESH)).hasMessageEndingWith(": is a folder, not a tree file");
    }

    /** Every byte of a kd-tree's and a BVH's file flipped in turn: each file refused, none loaded, nothing else thrown. */
    @Test void aByteFlippedAnywhereIsRefused() {
        for (byte[] file : new byte[][] {kdFile(), bvhFile()}) {
            for (int i = 0; i < file.length; i++) {
                byte[] bad = file.clone();
                bad[i] ^= (byte) (1 << (i % 8));
                String why = refusal(bad, MESH);
                if (i >= TreeFormat.PREFIX) assertThat(why).as("byte %d", i).contains("damaged: its checksum is ");
            }
        }
    }

    /** The file's two readers, its mapping and a stream, refuse a damaged or forged file in the same words. */
    @Test void theMappingAndTheStreamRefuseAlike(@TempDir Path dir) throws Exception {
        Path f = dir.resolve("t.kdtree");
        for (byte[] file : new byte[][] {kdFile(), bvhFile()}) {
            for (int i = 0; i < file.length; i += 37) {
                for (boolean forge : new boolean[] {false, true}) {
                    byte[] bad = file.clone();
                    bad[i] ^= 0x40;
                    if (forge) forged(bad);
                    Files.write(f, bad);
                    String streamed = outcome(() -> Saved.read(bad, MESH)).replace("test.kdtree: ", "");
                    String mapped = outcome(() -> TreeFile.load(f, MESH)).replace(f + ": ", "");
                    assertThat(mapped).as("byte %d, forged %s", i, forge).isEqualTo(streamed);
                    if (!forge && i >= TreeFormat.PREFIX) assertThat(mapped).contains("damaged: its checksum is ");
                }
            }
        }
    }

    /** "loaded" (a forged file may make a tree), or the refusal's message. */
    private static String outcome(org.assertj.core.api.ThrowableAssert.ThrowingCallable load) {
        Throwable t = org.assertj.core.api.Assertions.catchThrowable(load);
        if (t == null) return "loaded";
        assertThat(t).isInstanceOf(TreeFileException.class);
        return t.getMessage();
    }

    @Test void anotherMagicIsNotATreeFile() {
        byte[] file = kdFile();
        file[1] = 'X';
        assertThat(refusal(file, MESH)).isEqualTo("test.kdtree: not a tree file (it starts with \"\\x89XDT\\x0d\\x0a\\x1a\\x0a\", a tree file with "
                + "\"\\x89KDT\\x0d\\x0a\\x1a\\x0a\"); give a file written by --save-tree");
    }

    @Test void anotherVersionIsNamedWithThisOne() {
        byte[] file = kdFile();
        file[8] = 7;
        assertThat(refusal(file, MESH)).isEqualTo("test.kdtree: tree file format version 7; this version of kdtree reads version 1 only: "
                + "save the tree again with this version");
    }

    /** A stated size beyond {@link org.kdtree.limits.Limits#TREE_FILE}: refused before anything is allocated. */
    @Test void aStatedSizeBeyondTheLimitIsRefusedBeforeAllocating() {
        byte[] file = kdFile();
        ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN).putLong(16, 5L << 30);
        assertThat(refusal(file, MESH)).isEqualTo("test.kdtree: the header states 5368709120 bytes, more than a tree file may hold: "
                + "tree file (2047 MB)");
    }

    /** A count inside, with the checksum made to match: more items than the file's bytes hold. */
    @Test void aCountBeyondTheFilesBytesIsRefused() {
        byte[] file = kdFile();
        int nodeCount = 64 + TreeFormat.STATS;   // the builder's strings, then the root voxel and the budget: find the count by its value
        ByteBuffer b = ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN);
        int stated = b.getInt(64);   // the statistics' node count
        int at = -1;
        for (int i = nodeCount; i + 4 < file.length; i++) if (b.getInt(i) == stated) { at = i; break; }
        assertThat(at).as("where the node count is").isPositive();
        b.putInt(at, 1_000_000_000);
        assertThat(refusal(forged(file), MESH)).contains("damaged: it states 1000000000 of the nodes, more than its remaining");
    }

    /** Statistics that are not the tree's, in files whose checksum was made to match: the counts of a kd-tree, anything of a BVH. */
    @Test void statedStatisticsThatAreNotTheTreesAreRefused() {
        for (byte[] file : new byte[][] {kdFile(), bvhFile()}) {
            ByteBuffer b = ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN);
            b.putInt(68, b.getInt(68) + 1);   // leaves
            assertThat(refusal(forged(file), MESH)).contains("damaged: the statistics it states (TreeStats[nodes=");
        }
        byte[] bvh = bvhFile();
        ByteBuffer b = ByteBuffer.wrap(bvh).order(ByteOrder.LITTLE_ENDIAN);
        b.putDouble(112, b.getDouble(112) + 1);   // expected cost: a BVH's is counted again on loading
        assertThat(refusal(forged(bvh), MESH)).contains("damaged: the statistics it states");
    }

    /** Node links out of range, in files whose checksum was made to match: named by the node. */
    @Test void aLinkOutOfRangeIsRefusedNamingTheNode() {
        byte[] file = kdFile();
        int nodes = nodesAt(file);
        ByteBuffer b = ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN);
        int root = b.getInt(nodes);                      // the root's word: its right child above the axis bits (2 for 3-D)
        b.putInt(nodes, (5000 << 2) | (root & 3));
        assertThat(refusal(forged(file), MESH)).contains("damaged: node 0 links to children 1 and 5000, outside the");
        byte[] twice = kdFile();
        ByteBuffer.wrap(twice).order(ByteOrder.LITTLE_ENDIAN).putInt(nodes, (1 << 2) | (root & 3));   // right child = left child
        assertThat(refusal(forged(twice), MESH)).contains("damaged: node 0 links to children 1 and 1");
    }

    @Test void aBvhLinkOutOfRangeIsRefusedNamingTheNode() {
        byte[] file = bvhFile();
        int stated = ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN).getInt(64);
        int links = bvhLinksAt(file, stated);
        ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN).putInt(links, 9999);
        assertThat(refusal(forged(file), MESH)).contains("damaged: node 0 links to children 9999 and 10000, outside the " + stated + " nodes");
        byte[] loop = bvhFile();
        ByteBuffer.wrap(loop).order(ByteOrder.LITTLE_ENDIAN).putInt(links + 4, 0);   // node 1 points back at the root
        assertThat(refusal(forged(loop), MESH)).contains("damaged: node 1 links to children 0 and 1");
    }

    /** Where a kd-tree file's nodes start: after its count, which equals the statistics' node count, after the root voxel and budget. */
    private static int nodesAt(byte[] file) {
        ByteBuffer b = ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN);
        int stated = b.getInt(64);
        int refsBytes = 4 * (int) b.getLong(64 + 24);
        int at = file.length - 4 - refsBytes - 4 - 12 * stated;
        assertThat(b.getInt(at - 4)).as("the node count before the nodes").isEqualTo(stated);
        return at;
    }

    /** Where a BVH file's links start: after the count of nodes and their boxes. */
    private static int bvhLinksAt(byte[] file, int nodes) {
        ByteBuffer b = ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN);
        int prims = b.getInt(32);   // every primitive once, in leaf order
        int at = file.length - 4 - 4 * prims - 4 - 8 * nodes;
        assertThat(b.getInt(at - 48 * nodes - 4)).as("the node count before the boxes").isEqualTo(nodes);
        return at;
    }

    @Test void aSceneGivenForATreeIsNotATreeFile(@TempDir Path dir) throws Exception {
        Path obj = dir.resolve("mesh.obj");
        Files.writeString(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        assertThatThrownBy(() -> TreeFile.load(obj, MESH)).isInstanceOf(TreeFileException.class)
                .hasMessage(obj + ": not a tree file (it starts with \"v 0 0 0\\x0a\", a tree file with \"\\x89KDT\\x0d\\x0a\\x1a\\x0a\"); "
                        + "give a file written by --save-tree");
    }

    @Test void aTreeGivenForASceneIsNamedAsOne(@TempDir Path dir) throws Exception {
        for (String name : new String[] {"tree.obj", "tree.kdtree", "tree.json", "tree.scene2d", "tree.csv"}) {
            Path f = dir.resolve(name);
            Files.write(f, kdFile());
            String expected = f + ": is a saved tree (--save-tree), not a scene or point file: give the scene it was built over, and "
                    + "this file with --tree";
            assertThatThrownBy(() -> PrimitivesReader.read(f)).as(name).hasMessage(expected);
            if (name.endsWith(".obj") || name.endsWith(".json")) assertThatThrownBy(() -> PrimitivesReader.readMesh(f)).hasMessage(expected);
            if (name.endsWith(".json")) assertThatThrownBy(() -> PrimitivesReader.readScene(f)).hasMessage(expected);
            if (name.endsWith(".scene2d")) assertThatThrownBy(() -> PrimitivesReader.readScene2D(f)).hasMessage(expected);
            if (name.endsWith(".csv")) assertThatThrownBy(() -> PrimitivesReader.readPoints(f)).hasMessage(expected);
        }
    }
}
