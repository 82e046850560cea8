package org.kdtree.kdtree;

import java.util.BitSet;
import org.kdtree.geom.Box;

/**
 * The splits of a built tree that do not beat the leaf they replace by their own SAH cost: in a
 * SAH tree, the splits its {@link SahBuilder#lookahead() lookahead} made past a local minimum and
 * kept because the subtree below ended cheaper (the talk's "a few more iterations"). Without a
 * lookahead there are none: the SAH makes a split only where {@code C_V(p) < |T| Ki}.
 *
 * <p>Read from the tree and its cost model alone, so the tree's layout needs no mark: at each
 * interior node, {@link SahCost} prices the split as the build did, with |T_L| and |T_R| the
 * distinct primitives of each child's leaves (which are the child's references), against the
 * leaf of the node's own.
 */
public final class SplitsPastLocalMinimum {
    private SplitsPastLocalMinimum() {
    }

    /**
     * {@return the interior nodes whose split's cost {@code C_V(p)} is not below the leaf's {@code |T| Ki}}
     *
     * @param tree a kd-tree (a SAH tree for the answer to mean a lookahead)
     * @param lambda the lambda it was built with, the SAH's weight of a plane that leaves one child empty
     */
    public static BitSet of(KdTree tree, double lambda) {
        BitSet past = new BitSet();
        Distinct distinct = new Distinct(tree);
        tree.walk(new TreeVisitor() {
            @Override public void interior(int node, int depth, Box voxel, int axis, double split) {
                SahCost sah = new SahCost(tree.costModel(), lambda, voxel);
                int n = distinct.in(node), nl = distinct.in(tree.leftChild(node)), nr = distinct.in(tree.rightChild(node));
                if (!(sah.cost(axis, split, nl, nr) < sah.leafCost(n))) past.set(node);
            }

            @Override public void leaf(int node, int depth, Box voxel, int from, int to) { }
        });
        return past;
    }

    /** Counts the distinct primitives of a subtree's leaves, stamping each primitive seen with the count's number. */
    private static final class Distinct {
        private final KdTree tree;
        private final int[] stamp;
        private int count;

        Distinct(KdTree tree) {
            this.tree = tree;
            int most = -1;
            for (int r : tree.refs) most = Math.max(most, r);
            stamp = new int[most + 1];
        }

        int in(int node) {
            count++;
            return mark(node);
        }

        private int mark(int node) {
            if (!tree.isLeaf(node)) return mark(tree.leftChild(node)) + mark(tree.rightChild(node));
            int fresh = 0;
            for (int i = tree.leafStart(node); i < tree.leafEnd(node); i++) {
                if (stamp[tree.refs[i]] != count) {
                    stamp[tree.refs[i]] = count;
                    fresh++;
                }
            }
            return fresh;
        }
    }
}
