package org.kdtree.check;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;
import org.kdtree.geom.Box;
import org.kdtree.geom.Tolerance;
import org.kdtree.kdtree.KdTree;
import org.kdtree.kdtree.KdTreeBuilder;
import org.kdtree.kdtree.MedianPlaneBuilder;

/**
 * The contract's quality tier, opt-in (for grading): a builder may honour every invariant and
 * still build a useless tree. Three checks, each on every {@link CourseScenes course scene}:
 * no split plane separates nothing (lies on its voxel's face and cuts off an empty slice, leaving the
 * whole voxel to the other child);
 * not (nearly) every leaf stops only because it reached the depth cap; the tree's expected SAH cost is no higher
 * than the median-plane builder's on the same scene.
 */
public final class QualityChecks {
    /** The share of leaves at the depth cap beyond which a builder is taken not to stop on its own. */
    static final double MOST_AT_CAP = 0.9;

    private QualityChecks() {
    }

    /** The checks' names, in the order of {@link #cases()} and {@link #check}. */
    public static final List<String> NAMES = List.of("planes separate something", "leaves stop before the depth cap",
            "expected cost at most the median plane's");

    /** One check of one scene's tree: throws {@link ContractViolation} when the tree fails it. */
    @FunctionalInterface
    private interface SceneCheck {
        void check(KdTreeBuilder builder, CourseScenes.Named scene, KdTree tree, double medianPlaneCost);
    }

    private static final List<SceneCheck> CHECKS = List.of(QualityChecks::planesSeparateSomething,
            QualityChecks::leavesStopBeforeTheCap, QualityChecks::costAtMostMedianPlanes);

    /** {@return the three quality checks, as cases run on all course scenes} */
    public static List<ContractCase> cases() {
        List<ContractCase> out = new java.util.ArrayList<>();
        for (int i = 0; i < NAMES.size(); i++) {
            SceneCheck c = CHECKS.get(i);
            out.add(new ContractCase(NAMES.get(i), b -> forEachScene(b, c)));
        }
        return out;
    }

    /**
     * Runs the three checks on one scene's tree (for grading, which builds the trees anyway).
     * @param builder the builder that built {@code tree}
     * @param scene the scene
     * @param tree its tree
     * @param medianPlaneCost the median-plane builder's expected cost on the scene
     * @return per check, in the order of {@link #NAMES}, null if it passed or what failed
     */
    public static List<String> check(KdTreeBuilder builder, CourseScenes.Named scene, KdTree tree, double medianPlaneCost) {
        List<String> out = new java.util.ArrayList<>();
        for (SceneCheck c : CHECKS) {
            try {
                c.check(builder, scene, tree, medianPlaneCost);
                out.add(null);
            } catch (ContractViolation v) {
                out.add(v.getMessage());
            }
        }
        return out;
    }

    /** Runs {@code check} on every course scene; the violation names every scene that failed. */
    private static void forEachScene(Supplier<? extends KdTreeBuilder> builders, SceneCheck check) {
        Contract.requireStops(builders.get());
        List<String> failed = new ArrayList<>();
        for (CourseScenes.Named s : CourseScenes.all()) {
            KdTreeBuilder b = builders.get();
            try {
                KdTree tree = Contract.build(b, s.primitives(), s.name());
                double median = Contract.build(new MedianPlaneBuilder(), s.primitives(), s.name()).stats().expectedCost();
                check.check(b, s, tree, median);
            } catch (ContractViolation v) {
                failed.add(v.getMessage());
            }
        }
        if (!failed.isEmpty()) throw new ContractViolation(String.join(System.lineSeparator(), failed));
    }

    /**
     * A plane on the face of its voxel cuts off a flat, empty slice: one child is the voxel
     * itself with every primitive, and the recursion repeats until the depth cap.
     */
    static void planesSeparateSomething(KdTreeBuilder b, CourseScenes.Named scene, KdTree tree, double unused) {
        int[] useless = {0, -1};
        subtreeRefs(tree, 0, tree.bounds(), useless);
        ContractViolation.require(useless[0] == 0, String.format(Locale.ROOT,
                "%s: on %s, %d split planes separate nothing (the first at node %d): each lies on its voxel's face, so one"
                        + " child is the whole voxel with every primitive and the other an empty slice;"
                        + " findPlane() must choose a plane strictly inside the voxel that puts primitives on both sides.",
                b.name(), scene.name(), useless[0], useless[1]));
    }

    /** The references below {@code node}; counts in {@code useless} the planes that separate nothing. */
    private static long subtreeRefs(KdTree tree, int node, Box voxel, int[] useless) {
        if (tree.isLeaf(node)) return tree.leafSize(node);
        int axis = tree.axis(node);
        double x = tree.split(node);
        long left = subtreeRefs(tree, tree.leftChild(node), voxel.lowerPart(axis, x), useless);
        long right = subtreeRefs(tree, tree.rightChild(node), voxel.upperPart(axis, x), useless);
        // a plane on the face cuts off a flat slice; if the slice is empty, the other child is the whole
        // voxel with every primitive again (a flat slice holding the primitives that lie in it is the SAH's flat cell)
        boolean emptySlice = x <= voxel.min(axis) && left == 0 || x >= voxel.max(axis) && right == 0;
        if (emptySlice && voxel.extent(axis) > 0 && useless[0]++ == 0) useless[1] = node;
        return left + right;
    }

    /**
     * A leaf at the cap was cut short by the base class's safety net, not by terminate(). Good
     * builders leave some there (the SAH a third of them on tight clusters, the median plane half),
     * a builder that stops only at the cap nearly all.
     */
    static void leavesStopBeforeTheCap(KdTreeBuilder b, CourseScenes.Named scene, KdTree tree, double unused) {
        int cap = b.depthCap(scene.primitives().size());
        int atCap = 0, leaves = 0;
        for (TreeInspector.Leaf l : new TreeInspector(tree).leaves()) {
            leaves++;
            if (l.depth() >= cap) atCap++;
        }
        ContractViolation.require(atCap <= MOST_AT_CAP * leaves, String.format(Locale.ROOT,
                "%s: on %s, %d of %d leaves lie at the depth cap (%d): the cap, not terminate(), stopped them;"
                        + " terminate() should stop where splitting no longer pays.",
                b.name(), scene.name(), atCap, leaves, cap));
    }

    /** The point of a builder: a cheaper tree than the simplest one. */
    static void costAtMostMedianPlanes(KdTreeBuilder b, CourseScenes.Named scene, KdTree tree, double median) {
        double own = tree.stats().expectedCost();
        ContractViolation.require(own <= median * (1 + Tolerance.COST_SLACK), String.format(Locale.ROOT,
                "%s: on %s, the tree's expected SAH cost is %.2f, %.2f times the median-plane builder's %.2f;"
                        + " a builder should do at least as well as the median plane.",
                b.name(), scene.name(), own, own / median, median));
    }
}
