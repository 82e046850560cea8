/**
 * The kd-tree, built, stored and traversed, in one package so that its arrays stay its own.
 * Building: {@link org.kdtree.kdtree.KdTreeBuilder} (the talk's Algorithm 1, written once for
 * every builder; subclasses decide {@code terminate} and {@code findPlane}) over one node store,
 * viewed as {@link org.kdtree.kdtree.BuildNode}; its partition step; the median-plane,
 * object-median, sliding-midpoint and SAH builders with the SAH's plane searches;
 * {@link org.kdtree.kdtree.Supervisor}, which runs an untrusted (a student's) builder on a thread
 * of its own within deadlines and names its faults ({@link org.kdtree.kdtree.BuilderFault}).
 * The tree: {@link org.kdtree.kdtree.KdTree} (immutable flat arrays), the writer builders emit
 * nodes into, the walker, and the node layout, which is {@link org.kdtree.kdtree.Nodes}'s alone.
 * Traversal: the Havran-style stack traversal ({@link org.kdtree.kdtree.Traverser}), closest,
 * any and all hits, with a listening loop and a silent one.
 *
 * <p><b>Reading order</b> (docs/algorithms.md, "Reading the code"): the files a student reads,
 * in order, and the question each answers.
 * <ol>
 * <li>{@code KdTreeBuilder}: how is any tree built? Algorithm 1, {@code recConst}, once for every
 * builder: ask {@code terminate}, ask {@code findPlane}, cut, recurse (and take back a split
 * made on trial that did not pay).</li>
 * <li>{@code BuildNode}: what does a builder see of a node T, V? Its voxel, depth, references,
 * their clipped bounds, and its sorted events.</li>
 * <li>{@code CyclingAxisBuilder}, {@code MedianPlaneBuilder}, {@code ObjectMedianBuilder}: the
 * simplest answers to the two questions (talk 3.2).</li>
 * <li>{@code SahBuilder}: the SAH's answers (talk 3.3): {@code terminate} searches the best
 * plane and compares it with the leaf, {@code findPlane} returns it.</li>
 * <li>{@code SahCost}: what does one plane cost? {@code C_V(p)}, with lambda for empty space.</li>
 * <li>{@code SahSplit}: which plane is best? The first of least cost, planar primitives on the
 * cheaper side.</li>
 * <li>{@code NaivePlaneSearch}: the candidates counted one by one, O(N^2).</li>
 * <li>{@code SortedPlaneSearch}: each node's events sorted, then swept, O(N log^2 N).</li>
 * <li>{@code EventCode}, {@code EventRoot}, {@code EventSweep}, {@code EventSplit}: O(N log N)
 * (Wald and Havran 2006, 4.3): what an event is, the one sort at the root, the sweep, and the
 * split that keeps the children's events sorted ({@code EventSort}, the one sort, packs them in
 * longs).</li>
 * <li>{@code Partition}, {@code BoundsSplit}: where does a primitive go, and what is left of it
 * there (perfect splits)?</li>
 * <li>{@code NodeStore}: where do the nodes of a build live? One level per depth, in either form.</li>
 * <li>{@code KdTreeWriter}, {@code Nodes}, {@code KdTree}: the tree written depth first, its
 * node layout, and the finished tree.</li>
 * <li>{@code Traverser}: how does a ray go through it? Near and far child, tMin, tMax, tSplit
 * (talk 4.3).</li>
 * <li>Then, as needed: {@code SahSettings} and {@code Quality} (settings and presets),
 * {@code BinnedPlaneSearch} (the approximate search), the safety nets
 * ({@code SplitOutcome}, {@code ReferenceBudget}), {@code Supervisor} (a student's builder run
 * under deadlines), {@code MeshTraversal} and {@code Mailbox} (fast tracing).</li>
 * </ol>
 *
 * <p>Layer 4: it may use {@code limits}, {@code geom}, {@code shape} and {@code accel}; never the
 * bounding volume hierarchy, its sibling, nor any package above it, so a builder of a student's
 * jar joins without a change here.
 */
package org.kdtree.kdtree;
