package org.kdtree.kdtree;

/**
 * The per-lane work of the kd-tree's packet loop ({@link PacketTraversal}), behind one narrow
 * interface, Lucene's {@code VectorUtilSupport} shape: the loop is written once and calls the
 * kernel chosen once at start-up ({@link org.kdtree.accel.Vectorization#kernel}): {@link ScalarPacketKernel}
 * (Java 17, a lane at a time) or {@code VectorPacketKernel} (src/vector, the Vector API, several
 * lanes a compare). Both do for each lane exactly the single-ray loop's arithmetic ({@link
 * MeshTraversal}), so every ray's answer is its single-ray answer, bit for bit.
 */
interface PacketKernel {
    /**
     * The node kernel: each lane of {@code active} takes its {@code tSplit = (plane - origin) *
     * inverse} on {@code axis} and goes, by the single-ray rule against its widened interval {@code
     * [lo, hi]}, near ({@code tSplit > hi}), far ({@code tSplit < lo}) or both; {@link
     * PacketLanes#toNear} and {@link PacketLanes#toFar} receive the lanes that go each way. For
     * every lane that goes far, {@code farMin[at + lane]} and {@code farMax[at + lane]} receive
     * its interval beyond the plane (from its tSplit, or its interval's start where it only goes
     * far or tSplit is NaN: a ray in the plane); a lane that goes both ways has its near interval
     * cut at its tSplit (unless NaN). What it writes for other lanes at {@code at} is unspecified.
     *
     * @param lanes  the packet's lanes
     * @param active the lanes at this node
     * @param axis   the split plane's axis
     * @param plane  its position
     * @param farMin receives the far child's interval starts, from {@code at}
     * @param farMax receives their ends
     * @param at     where lane 0's entry goes
     */
    void node(PacketLanes lanes, long active, int axis, double plane, double[] farMin, double[] farMax, int at);

    /**
     * The node kernel's other half, where a saved far child is taken up: each lane of {@code saved}
     * whose interval there starts ({@code farMin[at + lane]}) no farther than its closest hit so far
     * (widened by the slack, the single-ray loop's test) takes that interval, {@code farMin} to
     * {@code farMax}, as its own, with its widened ends {@code lo} and {@code hi}.
     * {@return the lanes that take it up}
     *
     * @param lanes  the packet's lanes
     * @param saved  the lanes saved with the child (none blocked)
     * @param farMin their intervals' starts, from {@code at}
     * @param farMax their ends
     * @param at     where lane 0's entry is
     */
    long resume(PacketLanes lanes, long saved, double[] farMin, double[] farMax, int at);

    /**
     * The leaf kernel, closest hit: each lane of {@code active} tests the triangles of references
     * {@code refs[start]} to {@code refs[end - 1]} (their corners {@code 9 refs[r]} on in {@code
     * corners}) in that order with the watertight test, keeping in its best hit the closer, or of
     * two equally close the lower primitive.
     *
     * @param lanes   the packet's lanes
     * @param active  the lanes that test
     * @param refs    the tree's references
     * @param start   the leaf's first reference
     * @param end     one past its last
     * @param corners the mesh's corners, 9 a triangle
     */
    void closest(PacketLanes lanes, long active, int[] refs, int start, int end, double[] corners);

    /**
     * The leaf kernel, any hit: as {@link #closest}, each lane stopping at its first hit.
     * {@return the lanes that hit}
     *
     * @param lanes   the packet's lanes
     * @param active  the lanes that test
     * @param refs    the tree's references
     * @param start   the leaf's first reference
     * @param end     one past its last
     * @param corners the mesh's corners, 9 a triangle
     */
    long any(PacketLanes lanes, long active, int[] refs, int start, int end, double[] corners);
}
