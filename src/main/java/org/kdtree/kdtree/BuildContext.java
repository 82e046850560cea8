package org.kdtree.kdtree;

import org.kdtree.shape.Primitives;

/** What a builder's decisions may consult besides the node itself: the whole build's inputs. */
public interface BuildContext {
    /** {@return the primitives being built over} */
    Primitives primitives();

    /** {@return the depth cap in force for this build (Kmaxdepth, or its default {@code 8 + 1.3 log2 N})} */
    int depthCap();

    /**
     * {@return the smallest subtree (in references) handed to another thread}; {@code Integer.MAX_VALUE} in a one-thread build.
     */
    int forkThreshold();
}
