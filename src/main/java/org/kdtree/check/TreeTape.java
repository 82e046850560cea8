package org.kdtree.check;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;
import org.kdtree.accel.CostModel;
import org.kdtree.geom.Box;
import org.kdtree.geom.SplitPlane;
import org.kdtree.kdtree.BuildContext;
import org.kdtree.kdtree.BuildNode;
import org.kdtree.kdtree.BuilderFault;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.kdtree.KdTreeWriter;
import org.kdtree.shape.InvalidGeometryException;
import org.kdtree.shape.Primitives;

/**
 * The builds of one graded builder, sent from where its untrusted code ran (a boxed JVM) to the
 * trusted side that grades them, so that the grade is made where the student's code cannot reach.
 *
 * <p>The untrusted side runs the checks as usual under a {@link Recorder}: every
 * {@link Contract#build} of the graded builder is run, and its outcome (the tree, node by node, or
 * the builder's fault) written to the tape. The trusted side runs the very same checks under a
 * {@link Player}: each {@link Contract#build} of the {@linkplain Player#builder() stand-in builder} takes the
 * next record instead of running code, after checking that it is of the scene the check builds; it
 * computes the root voxel itself and writes the tree itself, so every invariant is checked on the
 * trusted side. Whatever the untrusted side writes into the tape (its own bytes, a forged tape) is
 * at most a tree, checked like any other, or a {@link Mismatch}: a record of another scene, a
 * malformed record, the tape ending early.
 *
 * <p>What is not checked: the build times (measured on the untrusted side, for the report only),
 * and where a tree came from (a builder may call the library's own builders).
 */
public abstract class TreeTape {
    private static final int MAGIC = 0x4b445431; // "KDT1"
    private static final byte BUILD = 'B', TREE = 'T', FAULT = 'F', GEOMETRY = 'G', OTHER = 'X', END = 'E';
    private static final byte LEAF = 0, INTERIOR = 2;
    /** The most nodes and references a tree on the tape may have: far above any contract or course scene's tree (at most 64 references a primitive). */
    static final int MOST_NODES = 1 << 23, MOST_REFS = 1 << 24;

    /** The builder classes whose stopping was checked once ({@link Contract#requireStops}), for this tape alone. */
    final Map<Class<?>, Optional<ContractViolation>> stops = new HashMap<>();

    private TreeTape() {
    }

    /** {@return whether this tape builds (or replays) {@code builder}'s trees} */
    abstract boolean takes(KdTreeBuilder builder);

    /** A build of {@code builder} on {@code prims}, recorded or replayed; a builder's fault is thrown as {@link BuilderFault}. */
    abstract KdTree build(KdTreeBuilder builder, Primitives prims, String scene, java.util.function.Supplier<KdTree> run);

    /** {@return how long the last build took on the untrusted side, in milliseconds} */
    public abstract double lastMillis();

    /**
     * The tape does not match the checks that read it: another scene, a malformed record, the
     * end too early or too late. An {@link Error}, not an exception, so that no check's handler
     * takes it for a failure of the builder's: the replay stops, and the grade says so.
     */
    public static final class Mismatch extends Error {
        private static final long serialVersionUID = 1L;

        /** Whether the tape just ended early. */
        private final boolean early;

        Mismatch(String message) {
            this(message, false);
        }

        Mismatch(String message, boolean early) {
            super(message);
            this.early = early;
        }

        /** {@return whether the tape just ended early (its writer died), rather than said something else} */
        public boolean early() {
            return early;
        }
    }

    /**
     * The untrusted side: runs the graded builder's builds and writes each outcome.
     */
    public static final class Recorder extends TreeTape {
        private final DataOutputStream out;
        private final Class<?> graded;
        private double lastMillis;

        /**
         * Starts the tape: its header names the builder.
         * @param out where the tape goes (the box's report channel)
         * @param graded a builder of the graded class (its builds are recorded; others run as usual)
         * @throws UncheckedIOException if the channel cannot be written
         */
        public Recorder(OutputStream out, KdTreeBuilder graded) {
            this.out = new DataOutputStream(new java.io.BufferedOutputStream(out, 1 << 16));
            this.graded = graded.getClass();
            write(() -> {
                this.out.writeInt(MAGIC);
                this.out.writeUTF(clip(graded.name()));
                this.out.flush();
            });
        }

        @Override boolean takes(KdTreeBuilder builder) {
            return builder.getClass() == graded;
        }

        @Override KdTree build(KdTreeBuilder builder, Primitives prims, String scene, java.util.function.Supplier<KdTree> run) {
            long t0 = System.nanoTime();
            KdTree tree;
            try {
                tree = run.get();
            } catch (BuilderFault f) {
                record(builder, prims, scene, t0, () -> {
                    out.writeByte(FAULT);
                    out.writeUTF(clip(f.builder()));
                    out.writeByte(f.kind().ordinal());
                    writeNullable(f.method());
                    out.writeInt(f.depth());
                    out.writeInt(f.size());
                    out.writeUTF(clip(f.problem()));
                    writeNullable(f.hint() == null ? null : clip(f.hint()));
                });
                throw f;
            } catch (InvalidGeometryException e) {
                record(builder, prims, scene, t0, () -> out.writeByte(GEOMETRY));
                throw e;
            } catch (RuntimeException e) {
                record(builder, prims, scene, t0, () -> {
                    out.writeByte(OTHER);
                    out.writeUTF(e.getClass().getSimpleName());
                    writeNullable(e.getMessage() == null ? null : clip(e.getMessage()));
                });
                throw e;
            }
            record(builder, prims, scene, t0, () -> {
                out.writeByte(TREE);
                out.writeInt(tree.budgetLeaves());
                writeNode(tree, 0, 0);
            });
            return tree;
        }

        @Override public double lastMillis() {
            return lastMillis;
        }

        /** Ends the tape: the trusted side reads nothing after this as part of it. */
        public void end() {
            write(() -> {
                out.writeByte(END);
                out.flush();
            });
        }

        private void record(KdTreeBuilder b, Primitives prims, String scene, long t0, IoBody outcome) {
            lastMillis = (System.nanoTime() - t0) / 1e6;
            write(() -> {
                out.writeByte(BUILD);
                out.writeUTF(clip(scene));
                out.writeInt(prims.size());
                out.writeDouble(lastMillis);
                out.writeInt(b.maxDepth());
                out.writeDouble(b.depthFactor());
                out.writeDouble(b.costModel().kt());
                out.writeDouble(b.costModel().ki());
                outcome.run();
                out.flush();
            });
        }

        /** Depth first, as {@link KdTreeWriter} takes it: a leaf's references, or an interior node's plane then both children. */
        private void writeNode(KdTree tree, int node, int depth) throws IOException {
            if (tree.isLeaf(node)) {
                out.writeByte(LEAF);
                out.writeInt(tree.leafSize(node));
                for (int i = tree.leafStart(node); i < tree.leafEnd(node); i++) out.writeInt(tree.ref(i));
                return;
            }
            out.writeByte(INTERIOR);
            out.writeByte(tree.axis(node));
            out.writeDouble(tree.split(node));
            writeNode(tree, tree.leftChild(node), depth + 1);
            writeNode(tree, tree.rightChild(node), depth + 1);
        }

        private void writeNullable(String s) throws IOException {
            out.writeBoolean(s != null);
            if (s != null) out.writeUTF(s);
        }

        private void write(IoBody body) {
            try {
                body.run();
            } catch (IOException e) {
                throw new UncheckedIOException("the report channel: " + e.getMessage(), e);
            }
        }
    }

    /**
     * The trusted side: replays a tape into the checks, through {@link #builder() a stand-in builder}.
     */
    public static final class Player extends TreeTape {
        private final DataInputStream in;
        private final String name;
        private double lastMillis;
        private int records;

        /**
         * Reads the tape's header.
         * @param in the tape (the box's report channel)
         * @throws Mismatch if it does not start as a tape does
         */
        public Player(InputStream in) {
            this.in = new DataInputStream(new java.io.BufferedInputStream(in, 1 << 16));
            this.name = read(() -> {
                if (this.in.readInt() != MAGIC) throw new Mismatch("the report does not start as one does");
                return this.in.readUTF();
            });
        }

        /** {@return the graded builder's name, as the tape says} */
        public String builderName() {
            return name;
        }

        /** {@return a new stand-in of the graded builder: its builds are the tape's next records} */
        public KdTreeBuilder builder() {
            return new StandIn(name);
        }

        @Override boolean takes(KdTreeBuilder builder) {
            return builder instanceof StandIn;
        }

        @Override KdTree build(KdTreeBuilder builder, Primitives prims, String scene, java.util.function.Supplier<KdTree> unused) {
            int record = ++records;
            return read(() -> {
                byte tag = in.readByte();
                if (tag == END) throw new Mismatch("the report ends before build " + record + " (of " + scene + ")");
                if (tag != BUILD) throw new Mismatch("build " + record + " is malformed");
                String said = in.readUTF();
                int n = in.readInt();
                if (!said.equals(clip(scene)) || n != prims.size())
                    throw new Mismatch("build " + record + " is of " + said + " (" + n + " primitives); the checks built "
                            + scene + " (" + prims.size() + ")");
                lastMillis = in.readDouble();
                settings(builder, record);
                Box root;
                try {
                    root = KdTreeBuilder.rootVoxel(prims);
                } catch (InvalidGeometryException e) { // the scene is invalid: only the library's own refusal may be recorded
                    if (in.readByte() != GEOMETRY) throw new Mismatch("build " + record + " (of " + scene + ") did not refuse invalid geometry");
                    throw e;
                }
                byte outcome = in.readByte();
                switch (outcome) {
                    case TREE -> {
                        KdTreeWriter w = new KdTreeWriter(prims.dimension());
                        int budgetLeaves = in.readInt();
                        if (budgetLeaves < 0 || budgetLeaves > MOST_NODES) throw new Mismatch("build " + record + " is malformed");
                        for (int i = 0; i < budgetLeaves; i++) w.budgetLeaf();
                        readNode(w, prims.dimension(), 0, new int[2], record);
                        return w.finish(prims, root, builder.costModel(), builder.name());
                    }
                    case FAULT -> throw fault(record);
                    case OTHER -> {
                        String type = in.readUTF();
                        String message = in.readBoolean() ? in.readUTF() : type;
                        throw new Thrown(message);
                    }
                    case GEOMETRY -> throw new Mismatch("build " + record + " (of " + scene + ") refused valid geometry");
                    default -> throw new Mismatch("build " + record + " is malformed");
                }
            });
        }

        @Override public double lastMillis() {
            return lastMillis;
        }

        /**
         * Reads the tape's end.
         * @throws Mismatch if the tape holds more builds than the checks made, or none of its end
         */
        public void end() {
            read(() -> {
                byte tag = in.readByte();
                if (tag == BUILD) throw new Mismatch("the report holds more builds than the checks made (" + records + ")");
                if (tag != END) throw new Mismatch("the report's end is malformed");
                return null;
            });
        }

        /**
         * Reads whatever follows the tape's end, to the end of the stream.
         * @return how many bytes followed it (written by the untrusted side after its report was done)
         */
        public long drainRest() {
            long after = 0;
            byte[] skip = new byte[1 << 16];
            try {
                for (int k; (k = in.read(skip)) >= 0; ) after += k;
            } catch (IOException closed) {
                // the stream ended
            }
            return after;
        }

        private void settings(KdTreeBuilder b, int record) throws IOException {
            int maxDepth = in.readInt();
            double factor = in.readDouble(), kt = in.readDouble(), ki = in.readDouble();
            try {
                b.maxDepth(maxDepth).depthFactor(factor).costModel(new CostModel(kt, ki));
            } catch (RuntimeException e) {
                throw new Mismatch("build " + record + " names settings no builder can have: " + e.getMessage());
            }
        }

        private BuilderFault fault(int record) throws IOException {
            String builder = in.readUTF();
            int kind = in.readByte();
            String method = in.readBoolean() ? in.readUTF() : null;
            int depth = in.readInt(), size = in.readInt();
            String problem = in.readUTF();
            String hint = in.readBoolean() ? in.readUTF() : null;
            if (kind < 0 || kind >= BuilderFault.Kind.values().length) throw new Mismatch("build " + record + " is malformed");
            return new BuilderFault(builder, BuilderFault.Kind.values()[kind], method, depth, size, problem, hint, null);
        }

        /** {@code counts}: nodes and references so far, each bounded. */
        private void readNode(KdTreeWriter w, int dimension, int depth, int[] counts, int record) throws IOException {
            if (++counts[0] > MOST_NODES || depth > KdTreeBuilder.DEPTH_LIMIT)
                throw new Mismatch("build " + record + " sent a tree deeper or larger than any builder can build");
            byte tag = in.readByte();
            if (tag == LEAF) {
                int k = in.readInt();
                if (k < 0 || (counts[1] += k) > MOST_REFS || counts[1] < 0)
                    throw new Mismatch("build " + record + " sent a leaf of " + k + " references");
                int[] refs = new int[Math.min(k, 1 << 12)]; // grown as they arrive, not as the tape claims
                for (int i = 0; i < k; i++) {
                    if (i == refs.length) refs = java.util.Arrays.copyOf(refs, (int) Math.min(k, 2L * refs.length));
                    refs[i] = in.readInt();
                }
                w.leaf(refs, k);
                return;
            }
            if (tag != INTERIOR) throw new Mismatch("build " + record + " is malformed");
            int axis = in.readByte();
            double split = in.readDouble();
            if (axis < 0 || axis >= dimension) throw new Mismatch("build " + record + " sent a plane on axis " + axis);
            int node = w.interior(axis, split);
            readNode(w, dimension, depth + 1, counts, record);
            w.setRightChild(node);
            readNode(w, dimension, depth + 1, counts, record);
        }

        private <T> T read(IoSupplier<T> body) {
            try {
                return body.get();
            } catch (EOFException e) {
                throw new Mismatch("the report ends early (after " + records + " builds)", true);
            } catch (IOException e) {
                throw new Mismatch("the report cannot be read: " + e.getMessage());
            } catch (IllegalArgumentException | IllegalStateException e) {
                if (e instanceof InvalidGeometryException) throw e;
                throw new Mismatch("the report is malformed: " + e.getMessage());
            }
        }
    }


    private static String clip(String s) {
        return s.length() <= 4000 ? s : s.substring(0, 4000);
    }

    /** What the graded builder's build threw on the untrusted side, other than its fault: its message, thrown again. */
    private static final class Thrown extends RuntimeException {
        private static final long serialVersionUID = 1L;

        Thrown(String message) {
            super(message);
        }
    }

    /** The graded builder on the trusted side: its name and settings; its code is never run (its trees are the tape's). */
    private static final class StandIn extends KdTreeBuilder {
        private final String name;

        StandIn(String name) {
            this.name = name;
        }

        @Override public String name() {
            return name;
        }

        @Override protected boolean terminate(BuildContext context, BuildNode node) {
            throw new UnsupportedOperationException("a replayed builder does not build");
        }

        @Override protected SplitPlane findPlane(BuildContext context, BuildNode node) {
            throw new UnsupportedOperationException("a replayed builder does not build");
        }
    }

    @FunctionalInterface
    private interface IoBody {
        void run() throws IOException;
    }

    @FunctionalInterface
    private interface IoSupplier<T> {
        T get() throws IOException;
    }
}
