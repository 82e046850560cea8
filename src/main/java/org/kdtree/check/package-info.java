/**
 * The builder contract without a test framework: its named cases ({@link org.kdtree.check.Contract}),
 * the invariants of every tree ({@link org.kdtree.check.TreeChecks}), the opt-in quality tier
 * ({@link org.kdtree.check.QualityChecks}) and the course's scenes ({@link org.kdtree.check.CourseScenes}; the contract's scenes
 * are generated in {@code generate}). The JUnit base classes students extend
 * ({@code org.kdtree.contract}, the artifact {@code kdtree-contract}) and the {@code grade} command
 * run the same cases, every build under a {@link org.kdtree.kdtree.Supervisor}. Uses {@code build}, {@code tree},
 * {@code shape}, {@code geom}, {@code limits} (the deadlines), {@code generate} (the generated
 * scenes) and {@code io} (the bundled scenes); used by {@code cli}.
 *
 * <p>Layer 8: it may use the library below it; only {@code cli} uses it.
 */
package org.kdtree.check;
