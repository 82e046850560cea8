/**
 * Every setting's allowed range, stated once ({@link org.kdtree.limits.Limits}), and the one
 * wording of a rejection ({@link org.kdtree.limits.Limit}): the API, the command line, the
 * scene files and the workbench all check against these.
 *
 * <p>Layer 1 of docs/architecture.md: it uses no other package of the library.
 */
package org.kdtree.limits;
