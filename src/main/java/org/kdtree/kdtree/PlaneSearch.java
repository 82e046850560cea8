package org.kdtree.kdtree;

/** An algorithm that finds the plane of least SAH cost for one node. */
interface PlaneSearch {
    /**
     * Offers every candidate plane of {@code node} to {@code best}.
     *
     * @param node the node whose voxel and primitives are searched
     * @param sah the SAH cost of that voxel
     * @param best keeps the cheapest plane offered
     */
    void search(BuildNode node, SahCost sah, SahSplit best);
}
