/**
 * Every scene and point set the code makes rather than reads, in one place, all drawn from one
 * seeded generator ({@link java.util.Random}, whose sequence the Java specification fixes, so a
 * seed gives the same scene on every machine): 2-D shapes ({@link org.kdtree.generate.Shapes}),
 * 3-D triangle meshes ({@link org.kdtree.generate.Meshes}, and the benchmark spec's grid of copies,
 * {@link org.kdtree.generate.MeshGrid}) and k-D points ({@link org.kdtree.generate.Points}). A name
 * means one scene: "clustered" is small objects Gaussian around a few centres placed uniformly
 * ({@code Clusters}), in 2-D, 3-D and k-D alike; "uniform" is small objects spread evenly. The
 * workbench, the builder contract and the course, the studies, the benchmarks and the tests
 * draw their generated scenes from here; the bundled scene files are read by {@code io}.
 *
 * <p>Layer 3: it may use {@code limits}, {@code geom} and {@code shape}.
 */
package org.kdtree.generate;
