/**
 * Worked examples a user starts from: the course assignment's builder (declared in {@code META-
 * INF/services}, found as a student's builder is, named by no other package) and the README's
 * library example.
 *
 * <p>Layer 8: it may use the library below it (it reads files with {@code io}); nothing uses
 * it.
 */
package org.kdtree.examples;
