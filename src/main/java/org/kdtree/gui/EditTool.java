package org.kdtree.gui;

/** What a left-button drag on the canvas does. */
public enum EditTool {
    SELECT("Select / move", "Drag an object to move it, drag a corner to resize it; Delete removes it"),
    RAY("Cast ray", "Drag from the ray's origin towards where it goes"),
    POINT("Add point", "Click to add a point"),
    SEGMENT("Add segment", "Drag from one end to the other"),
    RECT("Add rectangle", "Drag from one corner to the opposite one"),
    TRIANGLE("Add triangle", "Drag the base; the apex goes above its middle"),
    KNN("k-NN query", "Click (or drag) to place the query point of the nearest-neighbour stepper");

    private final String label;
    private final String help;

    EditTool(String label, String help) {
        this.label = label;
        this.help = help;
    }

    public String label() { return label; }
    public String help() { return help; }
}
