/**
 * How the library writes a user's files: whole or not at all ({@link org.kdtree.files.AtomicFile}:
 * a temporary file beside the target, moved into place atomically, so that an error, an
 * interruption or a second writer never leaves a mixed or half-written file). Whether an output
 * would overwrite an input is the command line's check, before any work (its {@code SameFile}).
 * The CSV tables it writes are read back one way ({@link org.kdtree.files.CsvFields}: a roster,
 * a class's grades, a study's rows).
 *
 * <p>Layer 1 of docs/architecture.md: it uses no other package of the library, so that every
 * package that writes a file (io, render, tradeoff, gui, cli) may use it.
 */
package org.kdtree.files;
