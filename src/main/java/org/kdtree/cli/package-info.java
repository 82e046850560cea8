/**
 * The command line (picocli): {@code gui} (the default), {@code stats}, {@code raycast},
 * {@code render}, {@code tradeoff}, {@code knn}; {@link org.kdtree.cli.Main} is the jar's entry
 * point, and every failure ends as one line.
 *
 * <p>Layer 10, the top: it may use every package.
 */
package org.kdtree.cli;
