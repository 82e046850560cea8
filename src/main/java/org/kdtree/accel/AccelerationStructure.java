package org.kdtree.accel;

import org.kdtree.geom.Box;

/**
 * What a ray tracer sees of a built acceleration structure, a kd-tree or a bounding volume
 * hierarchy: its statistics and, for each thread, a query over the primitives it was built
 * over. The benchmark, the renderer, the trade-off study and the workbench's comparison take
 * this, so that both structures are judged by the same rays, the same checksum and the same
 * cost model.
 */
public interface AccelerationStructure {
    /** {@return what kind of structure it is}: "kd-tree" or "bvh" */
    String kind();

    /**
     * {@return what its builder's safety nets did to it, one line each, for the statistics}: empty
     * when they did nothing (a kd-tree's reference budget may make leaves early)
     */
    default java.util.List<String> notes() { return java.util.List.of(); }

    /** {@return k, the dimension of its primitives} */
    int dimension();

    /** {@return the bounds of the primitives it holds} */
    Box bounds();

    /**
     * {@return which loop its fast queries run, in a few words}, for the benchmark's report: a
     * structure with a Vector API path says whether this JVM takes it (the BVH: whether the JDK has the Vector API)
     */
    default String describePath() { return "scalar (the Java 17 loop; no vector path for this structure)"; }

    /** {@return Kt and Ki: the cost model it was built and is judged by} */
    CostModel costModel();

    /** {@return its statistics}: nodes, leaves, depth, references, memory, expected cost under its cost model */
    TreeStats stats();

    /**
     * A new query object for one thread, the fastest this structure has (silent: it reports
     * nothing), over the primitives it was built over (bound once, at build time: a query takes
     * no second copy of them).
     *
     * @return the query
     * @throws IllegalArgumentException if it was built over primitives no ray is traced against (points)
     */
    RayQuery query();

    /**
     * A new query object for one thread that reports every step to {@code listener} (the
     * statistics per ray, the workbench's stepper); slower than {@link #query()}.
     *
     * @param listener is told each step of each query
     * @return the query
     * @throws IllegalArgumentException if it was built over primitives no ray is traced against (points)
     */
    RayQuery query(TraversalListener listener);

    /**
     * A new packet query for one thread over the triangle mesh it was built over: every structure
     * answers packets of rays, each ray exactly as {@link #query()} answers it alone. Whether its
     * loop traces a packet's rays together or each alone, {@link PacketQuery#tracesTogether} says
     * (the kd-tree's, for now, traces each ray through its fast single-ray loop).
     *
     * @return the packet query
     * @throws IllegalArgumentException if it was not built over a 3-D triangle mesh (packets are 3-D rays)
     */
    PacketQuery packetQuery();
}
