package org.kdtree.build;

import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.kdtree.bench.BenchScenes;
import org.kdtree.geom.Box;
import org.kdtree.geom.SplitPlane;
import org.kdtree.shape.Primitives;
import org.kdtree.shape.TriangleMesh;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

/**
 * The steps of the O(N log N) SAH build one at a time, to see where a build's time goes
 * (docs/performance.md, section 1). The set-up builds the scene's tree once with a builder
 * that counts the work (nodes searched, events swept, nodes split, events split, straddlers
 * clipped; printed) and keeps a random sample of real nodes of 4-15 references and of real
 * straddler clips. Each benchmark replays one step:
 * <ul>
 *   <li>{@code rootSearch}, {@code rootSplit}: the root's sweep of all its events, and its split
 *       (one big node: divide by the printed root events for the cost per event);</li>
 *   <li>{@code smallSearch}, {@code smallSplit}: the same for the sampled small nodes (per node);</li>
 *   <li>{@code clip}: the sampled {@code clipSplit} calls (per clip).</li>
 * </ul>
 * It sits in the builder's package because the steps are package-private.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(value = 1, jvmArgsAppend = {"-Xmx6g"})
public class EventStepsBenchmark {
    /** Sampled small nodes and clips. */
    static final int SAMPLE = 4096;
    private static final SahBuilder DEFAULTS = new SahBuilder();

    /** A scene as BuildBenchmark names it: uniform, clustered, surface, or an OBJ path. */
    @Param({"surface"})
    public String scene;

    /** Triangles of a generated scene (ignored for a file). */
    @Param({"69451"})
    public int n;

    private TriangleMesh mesh;
    private EventNode root;
    private SplitPlane rootPlane;
    private SahCost rootCost;
    private EventNode[] small;
    private SplitPlane[] smallPlane;
    private Clip[] clips;
    private final Box left = new Box(3), right = new Box(3);
    private final EventPlaneSearch search = new EventPlaneSearch();

    private record Clip(int prim, Box voxel, int axis, double xi) {
    }

    @Setup(Level.Trial)
    public void setUp() {
        mesh = BenchScenes.make(scene, n);
        Recorder recorder = new Recorder(mesh);
        recorder.build(recorder.counted);
        System.out.println(recorder.report());
        if (recorder.smallSeen < SAMPLE || recorder.clipped < SAMPLE)
            throw new IllegalArgumentException("scene " + scene + " is too small: it needs " + SAMPLE
                    + " splits of 4-15 references and " + SAMPLE + " straddler clips");
        root = (EventNode) DEFAULTS.makeRoot(mesh, mesh.bounds());
        rootCost = cost(root);
        SahSplit best = new SahSplit();
        search.search(root, rootCost, best);
        rootPlane = best.plane();
        System.out.printf("root: %,d events%n", Recorder.events(root));
        small = new EventNode[SAMPLE];
        smallPlane = recorder.smallPlanes;
        for (int i = 0; i < SAMPLE; i++) small[i] = EventNode.of(recorder.smallNodes[i], false);
        clips = recorder.clips;
    }

    /** The cost terms of a node with the default builder's Kt, Ki and lambda, as its terminate makes them. */
    private static SahCost cost(BuildNode node) {
        return new SahCost(DEFAULTS.costModel(), DEFAULTS.emptyWeight(), node.voxel());
    }

    @Benchmark
    public SahSplit rootSearch() {
        SahSplit best = new SahSplit();
        search.search(root, rootCost, best);
        return best;
    }

    @Benchmark
    public Children rootSplit() {
        return EventPartition.split(mesh, root, rootPlane, true);
    }

    /** What terminate does for a node: its cost terms, then the sweep of its 3 axes. */
    @Benchmark
    @OperationsPerInvocation(SAMPLE)
    public double smallSearch() {
        double sum = 0;
        for (EventNode node : small) {
            SahSplit best = new SahSplit();
            search.search(node, cost(node), best);
            sum += best.cost();
        }
        return sum;
    }

    @Benchmark
    @OperationsPerInvocation(SAMPLE)
    public int smallSplit() {
        int sum = 0;
        for (int i = 0; i < SAMPLE; i++) sum += EventPartition.split(mesh, small[i], smallPlane[i], true).left().size();
        return sum;
    }

    @Benchmark
    @OperationsPerInvocation(SAMPLE)
    public double clip() {
        double sum = 0;
        for (Clip c : clips) {
            mesh.clipSplit(c.prim, c.voxel, c.axis, c.xi, left, right);
            sum += left.max(c.axis) + right.min(c.axis);
        }
        return sum;
    }

    /** The default SAH build, counting its work and sampling (reservoir, fixed seed) small nodes and clips. */
    private static final class Recorder extends SahBuilder {
        final Primitives counted;
        final BuildNode[] smallNodes = new BuildNode[SAMPLE];
        final SplitPlane[] smallPlanes = new SplitPlane[SAMPLE];
        final Clip[] clips = new Clip[SAMPLE];
        private final Random random = new Random(42);
        long searched, swept, split, splitEvents, smallSeen, clipped;

        Recorder(TriangleMesh mesh) {
            counted = new Primitives() {
                @Override public int dimension() { return 3; }
                @Override public int size() { return mesh.size(); }
                @Override public void bounds(int i, Box dest) { mesh.bounds(i, dest); }
                @Override public void clip(int i, Box voxel, Box dest) { mesh.clip(i, voxel, dest); }
                @Override public void clipSplit(int i, Box voxel, int axis, double xi, Box l, Box r) {
                    long at = sampleSlot(clipped++);
                    if (at >= 0) clips[(int) at] = new Clip(i, voxel.copy(), axis, xi);
                    mesh.clipSplit(i, voxel, axis, xi, l, r);
                }
            };
        }

        /** Reservoir sampling: the slot for the {@code seen}-th item, or -1 to skip it. */
        private long sampleSlot(long seen) {
            if (seen < SAMPLE) return seen;
            long j = (long) (random.nextDouble() * (seen + 1));
            return j < SAMPLE ? j : -1;
        }

        @Override protected boolean terminate(BuildContext context, BuildNode node) {
            if (node.size() > 0 && node.depth() < context.depthCap()) {
                searched++;
                swept += events((EventNode) node);
            }
            return super.terminate(context, node);
        }

        @Override protected Children split(BuildContext context, BuildNode node, SplitPlane plane) {
            EventNode e = (EventNode) node;
            split++;
            splitEvents += events(e);
            if (node.size() >= 4 && node.size() < 16) {
                long at = sampleSlot(smallSeen++);
                if (at >= 0) {
                    smallNodes[(int) at] = new BuildNode(node.voxel().copy(), node.refs().clone(),
                            node.clippedBounds().clone(), node.depth());
                    smallPlanes[(int) at] = plane;
                }
            }
            return super.split(context, node, plane);
        }

        private static long events(EventNode e) {
            long m = 0;
            for (int a = 0; a < e.dimension(); a++) m += e.eventsTo(a) - e.eventsFrom(a);
            return m;
        }

        String report() {
            return String.format("whole build: %,d nodes searched, %,d events swept; %,d nodes split, %,d events split "
                    + "(%,d of 4-15 references); %,d straddler clips", searched, swept, split, splitEvents, smallSeen, clipped);
        }
    }
}
