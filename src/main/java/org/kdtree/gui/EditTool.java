package org.kdtree.gui;

/** What a left-button drag on the canvas does. */
enum EditTool {
    /** Selects, moves and resizes objects. */
    SELECT("Select / move", "Drag an object to move it, drag a corner to resize it; Delete removes it"),
    /** Casts the ray the traversal stepper follows. */
    RAY("Cast ray", "Drag from the ray's origin towards where it goes"),
    /** Adds a point. */
    POINT("Add point", "Click to add a point"),
    /** Adds a segment. */
    SEGMENT("Add segment", "Drag from one end to the other"),
    /** Adds a rectangle. */
    RECT("Add rectangle", "Drag from one corner to the opposite one"),
    /** Adds a triangle. */
    TRIANGLE("Add triangle", "Drag the base; the apex goes above its middle"),
    /** Places the k-NN stepper's query point. */
    KNN("k-NN query", "Click (or drag) to place the query point of the nearest-neighbour stepper");

    private final String label;
    private final String help;

    EditTool(String label, String help) {
        this.label = label;
        this.help = help;
    }

    /** {@return the tool's name, as menus and the tool bar show it} */
    public String label() { return label; }
    /** {@return a sentence on how to use the tool} */
    public String help() { return help; }
}
