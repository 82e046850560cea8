package org.kdtree.treefile;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.zip.CRC32C;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.Setting;
import org.kdtree.accel.TreeStats;
import org.kdtree.bvh.Bvh;
import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.shape.Primitives;
import org.kdtree.spec.BuilderSpec;
import org.kdtree.spec.Structures;

/** The one writer of tree files ({@link TreeFormat}): a structure, its builder's specification and its primitives' fingerprint. */
final class TreeFileWriter {
    private TreeFileWriter() {
    }

    /** What follows the builder: a structure's own arrays, of known length. */
    private interface Body {
        int kind();
        long bytes();
        void writeTo(Sink out) throws IOException;
    }

    static void write(OutputStream out, AccelerationStructure tree, BuilderSpec spec, Primitives primitives) throws IOException {
        if (tree.dimension() != primitives.dimension())
            throw new IllegalArgumentException("a " + tree.dimension() + "-D tree over " + primitives.dimension() + "-D primitives");
        Fingerprint f = Fingerprint.of(primitives);
        Body body = Structures.match(tree, TreeFileWriter::kdTree, TreeFileWriter::bvh);
        List<byte[]> builder = builder(spec);
        long length = TreeFormat.HEADER + TreeFormat.STATS + body.bytes() + TreeFormat.CHECKSUM;
        for (byte[] s : builder) length += 4 + s.length;
        length += 4;   // the count of settings
        Sink s = new Sink(out);
        s.bytes(TreeFormat.MAGIC);
        s.i32(TreeFormat.VERSION).i32(body.kind()).i64(length);
        s.i32(f.kind()).i32(f.dimension()).i32(f.count()).i32(0).i64(f.hash());
        s.f64(tree.costModel().kt()).f64(tree.costModel().ki());
        TreeStats st = tree.stats();
        s.i32(st.nodes()).i32(st.leaves()).i32(st.emptyLeaves()).i32(st.maxDepth()).f64(st.averageLeafDepth())
                .i64(st.references()).f64(st.averageRefsPerLeaf()).i64(st.memoryBytes()).f64(st.expectedCost());
        s.string(builder.get(0)).i32((builder.size() - 2) / 2);
        for (byte[] b : builder.subList(1, builder.size())) s.string(b);
        body.writeTo(s);
        s.finish();
    }

    /** The builder's name, each setting given as an option and its value, and the builder's summary of every setting, as UTF-8. */
    private static List<byte[]> builder(BuilderSpec spec) {
        List<String> texts = new ArrayList<>(List.of(spec.builder()));
        for (Setting<?> row : spec.settings().givenRows()) {
            texts.add(row.option());
            texts.add(String.valueOf(spec.get(row)));
        }
        texts.add(spec.describe());
        return texts.stream().map(t -> t.getBytes(StandardCharsets.UTF_8)).toList();
    }

    private static Body kdTree(KdTree tree) {
        Box root = tree.bounds();
        int[] nodes = tree.nodeArray(), refs = tree.refArray();
        int k = tree.dimension();
        return new Body() {
            @Override public int kind() { return TreeFormat.KD_TREE; }
            @Override public long bytes() { return 16L * k + 4 + 4 + 4L * nodes.length + 4 + 4L * refs.length; }
            @Override public void writeTo(Sink s) throws IOException {
                for (int a = 0; a < k; a++) s.f64(root.min(a));
                for (int a = 0; a < k; a++) s.f64(root.max(a));
                s.i32(tree.budgetLeaves()).i32(tree.nodeCount()).ints(nodes).i32(refs.length).ints(refs);
            }
        };
    }

    private static Body bvh(Bvh h) {
        int n = h.nodeCount(), k = h.dimension(), p = h.primitiveCount();
        double[] box = new double[2 * k * n];
        int[] link = new int[n], size = new int[n], prims = new int[p];
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < k; a++) {
                box[2 * k * i + a] = h.min(i, a);
                box[2 * k * i + k + a] = h.max(i, a);
            }
            link[i] = h.isLeaf(i) ? ~h.leafStart(i) : h.left(i);
            size[i] = h.isLeaf(i) ? h.leafSize(i) : 0;
        }
        for (int r = 0; r < p; r++) prims[r] = h.primitive(r);
        return new Body() {
            @Override public int kind() { return TreeFormat.BVH; }
            @Override public long bytes() { return 4 + 4 + 8L * box.length + 4L * n + 4L * n + 4 + 4L * p; }
            @Override public void writeTo(Sink s) throws IOException {
                s.i32(h.width()).i32(n).doubles(box).ints(link).ints(size).i32(p).ints(prims);
            }
        };
    }

    /** Little-endian output through one buffer, every byte counted into the CRC-32C that ends the file. */
    private static final class Sink {
        private final OutputStream out;
        private final ByteBuffer buffer = ByteBuffer.allocate(1 << 16).order(ByteOrder.LITTLE_ENDIAN);
        private final CRC32C crc = new CRC32C();

        Sink(OutputStream out) {
            this.out = out;
        }

        private Sink room(int bytes) throws IOException {
            if (buffer.remaining() < bytes) flush();
            return this;
        }

        Sink i32(int v) throws IOException { room(4).buffer.putInt(v); return this; }
        Sink i64(long v) throws IOException { room(8).buffer.putLong(v); return this; }
        Sink f64(double v) throws IOException { room(8).buffer.putDouble(v); return this; }

        Sink bytes(byte[] b) throws IOException { return chunks(b.length, 1, (at, n) -> buffer.slice().put(b, at, n)); }

        Sink string(byte[] utf8) throws IOException { return i32(utf8.length).bytes(utf8); }

        Sink ints(int[] a) throws IOException { return chunks(a.length, 4, (at, n) -> buffer.asIntBuffer().put(a, at, n)); }

        Sink doubles(double[] a) throws IOException { return chunks(a.length, 8, (at, n) -> buffer.asDoubleBuffer().put(a, at, n)); }

        /** Puts items {@code at .. at + n} of an array into the buffer from its position (a view of it, which moves nothing). */
        private interface Chunk {
            void put(int at, int n);
        }

        /** Puts an array of {@code length} items of {@code width} bytes, as many at a time as the buffer holds. */
        private Sink chunks(int length, int width, Chunk put) throws IOException {
            for (int at = 0; at < length; ) {
                int n = Math.min(length - at, room(width).buffer.remaining() / width);
                put.put(at, n);
                buffer.position(buffer.position() + width * n);
                at += n;
            }
            return this;
        }

        private void flush() throws IOException {
            buffer.flip();
            crc.update(buffer.array(), 0, buffer.limit());
            out.write(buffer.array(), 0, buffer.limit());
            buffer.clear();
        }

        /** Writes what is buffered, then the checksum of everything written. */
        void finish() throws IOException {
            flush();
            buffer.putInt((int) crc.getValue());
            out.write(buffer.array(), 0, 4);
            buffer.clear();
            out.flush();
        }
    }
}
