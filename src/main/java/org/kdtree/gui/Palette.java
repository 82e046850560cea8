package org.kdtree.gui;

import java.awt.Color;

/** The colours of the 2-D canvas, shared by the painter and the tests that read its pixels back. */
final class Palette {
    private Palette() {
    }

    /** The canvas's background. */
    public static final Color BACKGROUND = Color.WHITE;
    /** Fill of empty leaves: the talk's figures shade the voxels that hold nothing. */
    public static final Color EMPTY_VOXEL = new Color(0xD8, 0xE4, 0xD0);
    /** Split lines, clipped to the voxel they cut. */
    public static final Color SPLIT_LINE = new Color(0x20, 0x20, 0x20);
    /**
     * Split lines a lookahead kept past a local minimum (dashed): their own split does not beat
     * the leaf, the subtree below them does ({@link org.kdtree.kdtree.SplitsPastLocalMinimum}).
     */
    public static final Color LOOKAHEAD_SPLIT = new Color(0xD8, 0x18, 0x68);
    /** The outline of the root voxel. */
    public static final Color ROOT_BOX = new Color(0x60, 0x60, 0x60);
    /** Object outlines. */
    public static final Color OBJECT = new Color(0x2B, 0x5C, 0xB8);
    /** Object fills. */
    public static final Color OBJECT_FILL = new Color(0x9C, 0xB8, 0xE8);
    /** The selected leaf's voxel. */
    public static final Color HIGHLIGHT_VOXEL = new Color(0xFF, 0xF2, 0xA8);
    /** The objects of the selected leaf. */
    public static final Color HIGHLIGHT_OBJECT = new Color(0xE0, 0x6A, 0x00);
    /** The shape being edited. */
    public static final Color SELECTED_SHAPE = new Color(0xC0, 0x00, 0xC0);
    /** The cast ray. */
    public static final Color RAY = new Color(0xD0, 0x10, 0x10);
    /** The traversal stepper's current node. */
    public static final Color CURRENT_NODE = new Color(0xFF, 0xB0, 0x40);
    /** The near child of the current interior node. */
    public static final Color NEAR_CHILD = new Color(0x40, 0xB0, 0x40);
    /** The far child of the current interior node. */
    public static final Color FAR_CHILD = new Color(0x40, 0x80, 0xE0);
    /** Far children saved on the stack. */
    public static final Color STACKED = new Color(0xA0, 0x60, 0xE0);
    /** Objects tested in the current leaf. */
    public static final Color TESTED = new Color(0xE0, 0x30, 0x30);
    /** The closest hit. */
    public static final Color HIT = new Color(0x00, 0x00, 0x00);
    /** The nearest-neighbour stepper's query point and its search radius (the k-th best distance). */
    public static final Color QUERY = new Color(0xC0, 0x00, 0x80);
    /** Voxels the nearest-neighbour search pruned. */
    public static final Color PRUNED = new Color(0x70, 0x70, 0x70);
    /**
     * A bounding volume hierarchy's leaf boxes: a translucent tint, laid once per leaf, so that
     * overlapping leaves show darker where they overlap.
     */
    public static final Color BVH_LEAF = new Color(0x20, 0xA0, 0x98, 56);
    /** The outline of a bounding volume hierarchy's leaf boxes (its interior boxes' are greys by depth). */
    public static final Color BVH_LEAF_LINE = new Color(0x10, 0x80, 0x78);

    /**
     * {@return the outline colour of a bounding volume hierarchy's interior boxes at {@code depth}}:
     * near black at the root, lighter greys deeper (down to depth 8), so that the leaves' teal and
     * the stepper's saturated colours stay apart from them
     *
     * @param depth a node's depth, the root's 0
     */
    public static Color bvhDepth(int depth) {
        int grey = 0x20 + Math.min(depth, 8) * (0xA0 - 0x20) / 8;
        return new Color(grey, grey, grey);
    }

    /** Balls of the collisions view. */
    public static final Color BALL = new Color(0xE0, 0x50, 0x20);
}
