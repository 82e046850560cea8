package org.kdtree.treefile;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Arrays;
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
 * <p>A file is mapped, not read: its arrays are copied once, from the mapping into the tree's.
 */
final class TreeFileReader {
    private final String name;
    private final ByteBuffer in;

    private TreeFileReader(String name, ByteBuffer in) {
        this.name = name;
        this.in = in.order(ByteOrder.LITTLE_ENDIAN);
    }

    /** Reads the tree of {@code file} over {@code primitives}. */
    static SavedTree read(Path file, Primitives primitives) throws IOException {
        String name = file.toString();
        try (FileChannel ch = FileChannel.open(file, StandardOpenOption.READ)) {
            long size = ch.size();
            ByteBuffer prefix = ByteBuffer.allocate((int) Math.min(size, TreeFormat.PREFIX));
            while (prefix.hasRemaining() && ch.read(prefix, prefix.position()) > 0) { }
            long length = checkPrefix(name, prefix.flip(), size);
            return new TreeFileReader(name, ch.map(FileChannel.MapMode.READ_ONLY, 0, length)).read(primitives);
        }
    }

    /** Reads the tree of a stream (named {@code name} in errors) over {@code primitives}: the stated length is read into one buffer first. */
    static SavedTree read(InputStream stream, String name, Primitives primitives) throws IOException {
        byte[] prefix = stream.readNBytes(TreeFormat.PREFIX);
        long length = checkPrefix(name, ByteBuffer.wrap(prefix), Long.MAX_VALUE);
        byte[] all = Arrays.copyOf(prefix, (int) length);
        int got = stream.readNBytes(all, prefix.length, all.length - prefix.length);
        if (prefix.length + got < length) throw truncated(name, prefix.length + got, length);
        return new TreeFileReader(name, ByteBuffer.wrap(all)).read(primitives);
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

    private SavedTree read(Primitives primitives) throws TreeFileException {
        int end = in.capacity() - TreeFormat.CHECKSUM;
        CRC32C crc = new CRC32C();
        crc.update(in.duplicate().position(0).limit(end));
        int stored = in.getInt(end);
        if (stored != (int) crc.getValue())
            throw damaged(String.format(Locale.ROOT, "its checksum is %08x, its bytes' %08x", stored, (int) crc.getValue()));
        in.limit(end).position(TreeFormat.PREFIX - 12);
        int structure = in.getInt();
        in.position(TreeFormat.PREFIX);
        Fingerprint file = new Fingerprint(in.getInt(), in.getInt(), in.getInt(), skip(4).in.getLong());
        if (file.dimension() < 1 || file.dimension() > KdTree.MAX_DIMENSION || file.count() < 0)
            throw damaged("it states " + file.dimension() + "-D primitives, " + file.count() + " of them");
        String mismatch = file.mismatch(Fingerprint.of(primitives));
        if (mismatch != null) throw new TreeFileException(name, mismatch);
        CostModel cost = costModel(in.getDouble(), in.getDouble());
        TreeStats stats = new TreeStats(in.getInt(), in.getInt(), in.getInt(), in.getInt(), in.getDouble(), in.getLong(), in.getDouble(),
                in.getLong(), in.getDouble());
        BuilderSpec spec = spec(structure);
        String settings = string("the settings' summary");
        AccelerationStructure tree = structure == TreeFormat.KD_TREE ? kdTree(primitives, cost, spec.builder(), stats) : bvh(primitives, cost);
        if (in.hasRemaining()) throw damaged(in.remaining() + " bytes after the tree");
        if (!tree.stats().equals(stats))
            throw damaged("the statistics it states (" + stats + ") are not its tree's (" + tree.stats() + ")");
        return new SavedTree(tree, spec, settings, stats);
    }

    private TreeFileReader skip(int bytes) {
        in.position(in.position() + bytes);
        return this;
    }

    private CostModel costModel(double kt, double ki) throws TreeFileException {
        try {
            return new CostModel(Limits.KT.check("Kt", kt), Limits.KI.check("Ki", ki));
        } catch (IllegalArgumentException e) {
            throw damaged(e.getMessage());
        }
    }

    /** The builder and the settings it was given, checked as the command line checks them; it must make the file's structure. */
    private BuilderSpec spec(int structure) throws TreeFileException {
        String builder = string("the builder's name");
        if (!BuilderSpec.names().contains(builder))
            throw new TreeFileException(name, "built by '" + builder + "', a builder not loaded here (known: " + String.join(", ", BuilderSpec.names())
                    + "); give its plug-in with --plugin");
        if ((structure == TreeFormat.BVH) != builder.equals(BvhBuilder.NAME) || structure != TreeFormat.KD_TREE && structure != TreeFormat.BVH)
            throw damaged("it holds " + TreeFormat.structure(structure) + ", which the " + builder + " builder does not make");
        BuilderSpec spec = BuilderSpec.of(builder);
        int count = count("the settings", 8);
        for (int i = 0; i < count; i++) {
            String option = string("a setting's option"), value = string("a setting's value");
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

    private KdTree kdTree(Primitives primitives, CostModel cost, String builder, TreeStats stats) throws TreeFileException {
        int k = primitives.dimension();
        need(16L * k, "the root voxel");
        double[] min = new double[k], max = new double[k];
        in.asDoubleBuffer().get(min).get(max);
        skip(16 * k);
        int budgetLeaves = in.getInt();
        int[] nodes = ints(3L * count("the nodes", 12), "the nodes");
        int[] refs = ints(count("the references", 4), "the references");
        try {
            return KdTree.restore(primitives, new Box(min, max), cost, builder, nodes, refs, budgetLeaves, stats);
        } catch (IllegalArgumentException e) {
            throw damaged(e.getMessage());
        }
    }

    private Bvh bvh(Primitives primitives, CostModel cost) throws TreeFileException {
        int k = primitives.dimension();
        int width = in.getInt();
        int n = count("the nodes", 16L * k + 8);
        double[] box = new double[2 * k * n];
        need(8L * box.length, "the boxes");
        in.asDoubleBuffer().get(box);
        skip(8 * box.length);
        int[] link = ints(n, "the links"), size = ints(n, "the leaf sizes");
        int[] order = ints(count("the leaf order", 4), "the leaf order");
        try {
            return Bvh.restore(primitives, box, link, size, order, cost, width);
        } catch (IllegalArgumentException e) {
            throw damaged(e.getMessage());
        }
    }

    /** A count of items of {@code bytes} each, which the rest of the file must hold. */
    private int count(String what, long bytes) throws TreeFileException {
        need(4, what);
        int n = in.getInt();
        if (n < 0 || n * bytes > in.remaining())
            throw damaged("it states " + Integer.toUnsignedString(n) + " of " + what + ", more than its remaining " + in.remaining() + " bytes hold");
        return n;
    }

    private int[] ints(long n, String what) throws TreeFileException {
        need(4 * n, what);
        int[] a = new int[(int) n];
        in.asIntBuffer().get(a);
        skip(4 * a.length);
        return a;
    }

    private String string(String what) throws TreeFileException {
        int n = count(what, 1);
        byte[] b = new byte[n];
        in.get(b);
        return new String(b, StandardCharsets.UTF_8);
    }

    private void need(long bytes, String what) throws TreeFileException {
        if (bytes > in.remaining()) throw damaged(what + " run past the end of its " + in.limit() + " bytes");
    }

    private TreeFileException damaged(String why) {
        return new TreeFileException(name, "damaged: " + why);
    }
}
