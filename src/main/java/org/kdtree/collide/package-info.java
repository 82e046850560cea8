/**
 * Sphere (circle) queries against a static scene: every primitive overlapping a sphere, the
 * first contact of a moving sphere, exact tests per primitive kind, brute force as the oracle,
 * and a small ball simulation for the workbench.
 *
 * <p>Layer 6: it may use the packages of layers 1 to 5.
 */
package org.kdtree.collide;
