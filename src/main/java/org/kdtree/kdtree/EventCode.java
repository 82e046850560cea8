package org.kdtree.kdtree;

/**
 * The code of one event of the O(N log N) build (Wald and Havran 2006, section 4.3): its kind
 * and its primitive in one {@code int}, beside its position in a parallel {@code double} array.
 * <pre>
 *   bits 31..30  the kind: END 0, PLANAR 1, START 2
 *   bits 29..0   the primitive
 * </pre>
 * A primitive has, on each axis, a planar event where its clipped bounds are flat, else a start
 * (at its clipped minimum) and an end (at its clipped maximum). The events are numbered by
 * primitive, not by position in a node, so a split copies them unchanged.
 */
final class EventCode {
    static final int END = 0, PLANAR = 1, START = 2;
    /** Primitives are numbered in 30 bits. */
    static final int MAX_PRIMITIVES = 1 << 30;
    private static final int PRIMITIVE_MASK = MAX_PRIMITIVES - 1;

    private EventCode() {
    }

    static int of(int kind, int primitive) {
        return kind << 30 | primitive;
    }

    static int kind(int code) {
        return code >>> 30;
    }

    static int primitive(int code) {
        return code & PRIMITIVE_MASK;
    }
}
