package org.kdtree.treefile;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.zip.CRC32C;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.accel.CostModel;
import org.kdtree.accel.Setting;
import org.kdtree.accel.TreeStats;
import org.kdtree.bvh.Bvh;
import org.kdtree.bvh.BvhBuilder;
import org.kdtree.geom.Box;
import org.kdtree.kdtree.KdTree;
import org.kdtree.limits.Limits;
import org.kdtree.shape.Primitives;
import org.kdtree.spec.BuilderSpec;

/**
 * The one reader of tree files ({@link TreeFormat}). It decides in this order, each refusal one
 * line: the magic (not a tree file), the version (naming both), the stated length against
 * {@link Limits#TREE_FILE} and against the bytes there are (truncated), the checksum (damaged),
 * then every count, link and name inside (a file whose checksum was forged), the primitives'
 * fingerprint against the scene's, and the statistics against the tree's (a kd-tree's counts as
 * its links are checked, its expected cost taken as stated: {@link KdTree#restore}).
 *
 * <p>Every array is copied once, into the tree's: from a mapping of the file (whose checksum is
 * checked first), or from a stream through one small buffer (whose checksum is counted on the way
 * and checked before anything read is believed). Nothing is allocated beyond what the stated
 * length, within the limit, holds.
 */
final class TreeFileReader {
    private final String name;
    /** The structure field of the prefix: a kd-tree or a hierarchy. */
    private final int structure;
    private final Input in;

    private TreeFileReader(String name, int structure, Input in) {
        this.name = name;
        this.structure = structure;
        this.in = in;
    }

    /** Reads the tree of {@code file} over {@code primitives}: mapped, its checksum checked first. */
    static SavedTree read(Path file, Primitives primitives) throws IOException {
        String name = file.toString();
        try (FileChannel ch = FileChannel.open(file, StandardOpenOption.READ)) {
            long size = ch.size();
            ByteBuffer prefix = ByteBuffer.allocate((int) Math.min(size, TreeFormat.PREFIX));
            while (prefix.hasRemaining() && ch.read(prefix, prefix.position()) > 0) { }
            long length = checkPrefix(name, prefix.flip(), size);
            ByteBuffer all = ch.map(FileChannel.MapMode.READ_ONLY, 0, length).order(ByteOrder.LITTLE_ENDIAN);
            int end = (int) length - TreeFormat.CHECKSUM;
            CRC32C crc = new CRC32C();
            crc.update(all.duplicate().position(0).limit(end));
            checksum(name, all.getInt(end), (int) crc.getValue());
            return new TreeFileReader(name, all.getInt(12), new Input(name, all.position(TreeFormat.PREFIX).limit(end), null, 0, length))
                    .read(primitives);
        }
    }

    /**
     * Reads the tree of a stream (named {@code name} in errors) over {@code primitives}: through one
     * small buffer straight into the tree's arrays, its checksum counted on the way and checked
     * before any of what it read is believed.
     */
    static SavedTree read(InputStream stream, String name, Primitives primitives) throws IOException {
        byte[] prefix = stream.readNBytes(TreeFormat.PREFIX);
        long length = checkPrefix(name, ByteBuffer.wrap(prefix), Long.MAX_VALUE);
        Input in = new Input(name, ByteBuffer.allocate(1 << 16).order(ByteOrder.LITTLE_ENDIAN).limit(0), stream,
                length - TreeFormat.PREFIX - TreeFormat.CHECKSUM, length);
        in.crc.update(prefix);
        return new TreeFileReader(name, ByteBuffer.wrap(prefix).order(ByteOrder.LITTLE_ENDIAN).getInt(12), in).read(primitives);
    }

    /** {@return whether {@code start}, a file's first bytes, are a tree file's magic} */
    static boolean isTreeFile(byte[] start) {
        return start.length >= TreeFormat.MAGIC.length && Arrays.equals(start, 0, TreeFormat.MAGIC.length, TreeFormat.MAGIC, 0, TreeFormat.MAGIC.length);
    }

    /** Checks magic, version and stated length (against the limit and the {@code size} there is); returns the length. */
    private static long checkPrefix(String name, ByteBuffer prefix, long size) throws TreeFileException {
        prefix.order(ByteOrder.LITTLE_ENDIAN);
        byte[] start = new byte[Math.min(prefix.remaining(), TreeFormat.MAGIC.length)];
        prefix.get(0, start);
        if (!isTreeFile(start)) {
            if (start.length < TreeFormat.MAGIC.length && Arrays.equals(start, Arrays.copyOf(TreeFormat.MAGIC, start.length)))
                throw truncated(name, start.length, TreeFormat.HEADER);
            throw new TreeFileException(name, "not a tree file (it starts with " + shown(start) + ", a tree file with "
                    + shown(TreeFormat.MAGIC) + "); give a file written by --save-tree");
        }
        if (prefix.remaining() < TreeFormat.PREFIX) throw truncated(name, prefix.remaining(), TreeFormat.HEADER);
        int version = prefix.getInt(8);
        if (version != TreeFormat.VERSION)
            throw new TreeFileException(name, "tree file format version " + Integer.toUnsignedString(version) + "; this version of kdtree reads version "
                    + TreeFormat.VERSION + " only: save the tree again with this version");
        long length = prefix.getLong(16);
        long limit = (long) Limits.TREE_FILE.max() << 20;
        if (length < 0 || length > limit)
            throw new TreeFileException(name, String.format(Locale.ROOT, "the header states %s bytes, more than a tree file may hold: "
                    + "%s (%s MB)", Long.toUnsignedString(length), Limits.TREE_FILE.title(), (long) Limits.TREE_FILE.max()));
        if (length < TreeFormat.HEADER + TreeFormat.STATS + TreeFormat.CHECKSUM)
            throw new TreeFileException(name, "the header states " + length + " bytes, fewer than any tree file has: damaged");
        if (size != Long.MAX_VALUE && size != length) {
            if (size < length) throw truncated(name, size, length);
            throw new TreeFileException(name, "has " + size + " bytes, its header states " + length + ": damaged or appended to");
        }
        return length;
    }

    private static TreeFileException truncated(String name, long size, long stated) {
        return new TreeFileException(name, "truncated: " + size + " bytes of the " + stated + " a tree file needs");
    }

    /** The bytes as a reader recognises them: printable ones as text, the others as hex. */
    private static String shown(byte[] bytes) {
        StringBuilder s = new StringBuilder();
        for (byte b : bytes) s.append(b >= 0x20 && b < 0x7f ? String.valueOf((char) b) : String.format(Locale.ROOT, "\\x%02x", b & 0xff));
        return "\"" + s + "\"";
    }

    private static void checksum(String name, int stored, int counted) throws TreeFileException {
        if (stored != counted)
            throw new TreeFileException(name, String.format(Locale.ROOT, "damaged: its checksum is %08x, its bytes' %08x", stored, counted));
    }

    /** What a file holds, read in order but not yet believed: nothing here is used before the checksum is. */
    private record Raw(Fingerprint fingerprint, double kt, double ki, TreeStats stats, String builder,
                       List<String> settings, String summary, Body body) {
    }

    /** A structure's own arrays, as read. */
    private sealed interface Body permits KdBody, BvhBody {
    }

    private record KdBody(double[] min, double[] max, int budgetLeaves, int[] nodes, int[] refs) implements Body {
    }

    private record BvhBody(int width, double[] box, int[] link, int[] size, int[] order) implements Body {
    }

    private SavedTree read(Primitives primitives) throws IOException {
        Raw raw;
        try {
            raw = raw();
        } catch (TreeFileException e) {
            in.drainAndCheck();   // a damaged count misread: the checksum's line, if it fails, is the one to give
            throw e;
        }
        in.drainAndCheck();
        return believe(raw, primitives);
    }

    private Raw raw() throws IOException {
        if (structure != TreeFormat.KD_TREE && structure != TreeFormat.BVH) throw damaged("it holds " + TreeFormat.structure(structure));
        int kind = in.i32("the primitives"), dimension = in.i32("the dimension"), count = in.i32("the count");
        in.i32("the reserved field");
        Fingerprint file = new Fingerprint(kind, dimension, count, in.i64("the fingerprint"));
        if (file.dimension() < 1 || file.dimension() > KdTree.MAX_DIMENSION || file.count() < 0)
            throw damaged("it states " + file.dimension() + "-D primitives, " + file.count() + " of them");
        double kt = in.f64("Kt"), ki = in.f64("Ki");
        TreeStats stats = new TreeStats(in.i32("the statistics"), in.i32("the statistics"), in.i32("the statistics"), in.i32("the statistics"),
                in.f64("the statistics"), in.i64("the statistics"), in.f64("the statistics"), in.i64("the statistics"), in.f64("the statistics"));
        String builder = string("the builder's name");
        int given = count("the settings", 8);
        List<String> settings = new ArrayList<>();
        for (int i = 0; i < 2 * given; i++) settings.add(string("a setting"));
        String summary = string("the settings' summary");
        int k = file.dimension();
        Body body;
        if (structure == TreeFormat.BVH) {
            int width = in.i32("the width");
            int n = count("the nodes", 16L * k + 8);
            body = new BvhBody(width, in.doubles(new double[2 * k * n], "the boxes"), in.ints(new int[n], "the links"),
                    in.ints(new int[n], "the leaf sizes"), in.ints(new int[count("the leaf order", 4)], "the leaf order"));
        } else {
            double[] min = in.doubles(new double[k], "the root voxel"), max = in.doubles(new double[k], "the root voxel");
            int budgetLeaves = in.i32("the early leaves");
            int[] nodes = in.ints(new int[3 * count("the nodes", 12)], "the nodes");
            body = new KdBody(min, max, budgetLeaves, nodes, in.ints(new int[count("the references", 4)], "the references"));
        }
        if (in.remaining() > 0) throw damaged(in.remaining() + " bytes after the tree");
        return new Raw(file, kt, ki, stats, builder, settings, summary, body);
    }

    /** The structure {@code raw} holds over {@code primitives}, once every name, count and link in it is checked. */
    private SavedTree believe(Raw raw, Primitives primitives) throws TreeFileException {
        String mismatch = raw.fingerprint().mismatch(Fingerprint.of(primitives));
        if (mismatch != null) throw new TreeFileException(name, mismatch);
        CostModel cost = costModel(raw.kt(), raw.ki());
        BuilderSpec spec = spec(raw);
        AccelerationStructure tree;
        try {
            if (raw.body() instanceof KdBody kd)
                tree = KdTree.restore(primitives, new Box(kd.min(), kd.max()), cost, spec.builder(), kd.nodes(), kd.refs(), kd.budgetLeaves(),
                        raw.stats());
            else {
                BvhBody h = (BvhBody) raw.body();
                tree = Bvh.restore(primitives, h.box(), h.link(), h.size(), h.order(), cost, h.width());
            }
        } catch (IllegalArgumentException e) {
            throw damaged(e.getMessage());
        }
        if (!tree.stats().equals(raw.stats()))
            throw damaged("the statistics it states (" + raw.stats() + ") are not its tree's (" + tree.stats() + ")");
        return new SavedTree(tree, spec, raw.summary(), raw.stats());
    }

    private CostModel costModel(double kt, double ki) throws TreeFileException {
        try {
            return new CostModel(Limits.KT.check("Kt", kt), Limits.KI.check("Ki", ki));
        } catch (IllegalArgumentException e) {
            throw damaged(e.getMessage());
        }
    }

    /** The builder and the settings it was given, checked as the command line checks them; it must make the file's structure. */
    private BuilderSpec spec(Raw raw) throws TreeFileException {
        String builder = raw.builder();
        if (!BuilderSpec.names().contains(builder))
            throw new TreeFileException(name, "built by '" + builder + "', a builder not loaded here (known: " + String.join(", ", BuilderSpec.names())
                    + "); give its plug-in with --plugin");
        if ((structure == TreeFormat.BVH) != builder.equals(BvhBuilder.NAME) || structure != TreeFormat.KD_TREE && structure != TreeFormat.BVH)
            throw damaged("it holds " + TreeFormat.structure(structure) + ", which the " + builder + " builder does not make");
        BuilderSpec spec = BuilderSpec.of(builder);
        for (int i = 0; i + 1 < raw.settings().size(); i += 2) {
            String option = raw.settings().get(i), value = raw.settings().get(i + 1);
            Setting<?> row = BuilderSpec.allSettingRows().stream().filter(r -> r.option().equals(option)).findFirst()
                    .orElseThrow(() -> damaged("it gives " + option + ", which no builder here takes"));
            try {
                spec = with(spec, row, value);
            } catch (IllegalArgumentException e) {
                throw damaged("its setting " + option + " " + value + ": " + e.getMessage());
            }
        }
        return spec;
    }

    private static <T> BuilderSpec with(BuilderSpec spec, Setting<T> row, String text) {
        Class<T> type = row.type();
        Object value;
        if (type == Integer.class) value = Integer.valueOf(text);
        else if (type == Double.class) value = Double.valueOf(text);
        else if (type == Boolean.class && (text.equals("true") || text.equals("false"))) value = Boolean.valueOf(text);
        else if (type.isEnum()) value = Arrays.stream(type.getEnumConstants()).filter(c -> c.toString().equals(text)).findFirst()
                .orElseThrow(() -> new IllegalArgumentException("not one of its values"));
        else throw new IllegalArgumentException("not a value of " + type.getSimpleName());
        return spec.with(row, type.cast(value));
    }

    /** A count of items of {@code bytes} each, which the rest of the file must hold. */
    private int count(String what, long bytes) throws IOException {
        int n = in.i32(what);
        if (n < 0 || n * bytes > in.remaining())
            throw damaged("it states " + Integer.toUnsignedString(n) + " of " + what + ", more than its remaining " + in.remaining() + " bytes hold");
        return n;
    }

    private String string(String what) throws IOException {
        return new String(in.bytes(new byte[count(what, 1)], what), StandardCharsets.UTF_8);
    }

    private TreeFileException damaged(String why) {
        return new TreeFileException(name, "damaged: " + why);
    }

    /**
     * A file's bytes after the prefix, read in order and each read checked against the length
     * stated: from a mapping (the buffer is the whole file), or from a stream through one small
     * buffer, refilled as it empties, every byte counted into the checksum as it arrives.
     */
    private static final class Input {
        private final String name;
        private final ByteBuffer buffer;
        private final InputStream stream;
        /** Bytes of the stream before the checksum not yet in the buffer. */
        private long unread;
        private final long length;
        final CRC32C crc = new CRC32C();

        Input(String name, ByteBuffer buffer, InputStream stream, long unread, long length) {
            this.name = name;
            this.buffer = buffer;
            this.stream = stream;
            this.unread = unread;
            this.length = length;
        }

        /** {@return the bytes before the checksum not yet read} */
        long remaining() { return buffer.remaining() + unread; }

        private void need(long bytes, String what) throws TreeFileException {
            if (bytes > remaining()) throw new TreeFileException(name, "damaged: " + what + " run past the end of its " + length + " bytes");
        }

        /** Has at least {@code bytes} (at most the buffer's capacity, and at most {@link #remaining()}) in the buffer. */
        private ByteBuffer fill(int bytes) throws IOException {
            while (buffer.remaining() < bytes) {
                buffer.compact();
                int want = (int) Math.min(buffer.remaining(), unread);
                int got = stream.readNBytes(buffer.array(), buffer.position(), want);
                crc.update(buffer.array(), buffer.position(), got);
                buffer.position(buffer.position() + got).flip();
                unread -= got;
                if (got < want) throw new TreeFileException(name, "truncated: " + (length - TreeFormat.CHECKSUM - unread)
                        + " bytes of the " + length + " a tree file needs");
            }
            return buffer;
        }

        int i32(String what) throws IOException { need(4, what); return fill(4).getInt(); }
        long i64(String what) throws IOException { need(8, what); return fill(8).getLong(); }
        double f64(String what) throws IOException { need(8, what); return fill(8).getDouble(); }

        /** Puts items {@code at .. at + n} of an array from the buffer's position (through a view of it). */
        private interface Chunk {
            void get(int at, int n);
        }

        /** Reads an array of {@code length} items of {@code width} bytes, as many at a time as the buffer holds. */
        private void chunks(int length, int width, String what, Chunk get) throws IOException {
            need((long) length * width, what);
            for (int at = 0; at < length; ) {
                int n = Math.min(length - at, fill(width).remaining() / width);
                get.get(at, n);
                buffer.position(buffer.position() + width * n);
                at += n;
            }
        }

        int[] ints(int[] a, String what) throws IOException {
            chunks(a.length, 4, what, (at, n) -> buffer.asIntBuffer().get(a, at, n));
            return a;
        }

        double[] doubles(double[] a, String what) throws IOException {
            chunks(a.length, 8, what, (at, n) -> buffer.asDoubleBuffer().get(a, at, n));
            return a;
        }

        byte[] bytes(byte[] a, String what) throws IOException {
            chunks(a.length, 1, what, (at, n) -> buffer.slice().get(a, at, n));
            return a;
        }

        /** A stream's rest read and its checksum checked (a mapping's was, before anything was read). */
        void drainAndCheck() throws IOException {
            if (stream == null) return;
            while (remaining() > 0) {
                ByteBuffer b = fill((int) Math.min(remaining(), buffer.capacity()));
                b.position(b.limit());
            }
            byte[] end = stream.readNBytes(TreeFormat.CHECKSUM);
            if (end.length < TreeFormat.CHECKSUM)
                throw new TreeFileException(name, "truncated: " + (length - TreeFormat.CHECKSUM + end.length) + " bytes of the " + length
                        + " a tree file needs");
            checksum(name, ByteBuffer.wrap(end).order(ByteOrder.LITTLE_ENDIAN).getInt(), (int) crc.getValue());
        }
    }
}
