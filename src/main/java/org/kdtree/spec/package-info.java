/**
 * Picking a structure by name: the one table of builder settings
 * ({@link org.kdtree.spec.SettingsTable}, of {@link org.kdtree.accel.Setting} rows), what a structure is to be built with
 * ({@link org.kdtree.spec.BuilderSpec}), and the registry of builders by name
 * ({@link org.kdtree.spec.Builders}: the library's, those a jar on the class path lists through
 * {@link java.util.ServiceLoader}, and plug-in jars named at run time), and which of the two a
 * built structure is, for a saved tree's writer ({@link org.kdtree.spec.Structures}). This is the only layer
 * that names the concrete structures; everything below it works through
 * {@link org.kdtree.accel.AccelerationStructure}.
 *
 * <p>Layer 5: it may use {@code limits}, {@code geom}, {@code shape}, {@code accel},
 * {@code kdtree} and {@code bvh}.
 */
package org.kdtree.spec;
