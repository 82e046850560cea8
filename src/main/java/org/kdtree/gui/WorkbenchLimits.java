package org.kdtree.gui;

import java.util.List;
import org.kdtree.limits.Limit;

/**
 * The workbench's own ranges: its controls, not settings of the library, so they live with the
 * workbench rather than in {@code limits.Limits} (docs/limits.md lists them with the others).
 */
final class WorkbenchLimits {
    /** The workbench's 3-D preview width, in pixels (it renders on every change). */
    static final Limit PREVIEW_WIDTH = Limit.whole("preview width", 16, 4096);
    /** k of the workbench's nearest-neighbour stepper (each step shows the whole list of the k best). */
    static final Limit STEPPER_K = Limit.whole("stepper k", 1, 64);
    /** Balls of the workbench's collisions view (stepped and drawn every frame). */
    static final Limit BALLS = Limit.whole("balls", 1, 5_000);

    /** All of them, in the order of docs/limits.md. */
    static final List<Limit> ALL = List.of(PREVIEW_WIDTH, STEPPER_K, BALLS);

    private WorkbenchLimits() {
    }
}
