package org.kdtree.build;

/** An algorithm that finds the plane of least SAH cost for one node. */
public interface PlaneSearch {
    /** Offers every candidate plane of {@code node} to {@code best}. */
    void search(BuildNode node, SahCost sah, SahSplit best);
}
