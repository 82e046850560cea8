package org.kdtree.compare;

/**
 * The terms of a {@link TreeDistance}, each in [0, 1], and the weight of each in the total (the
 * weights sum to 1, so the total is in [0, 1] too). Equal weights: each term sees the tree from
 * another side, and none is known to matter more for every kind of data.
 */
public enum Term {
    /** Where the space is: large voxels or small ones (total variation of the volume histograms). */
    VOLUMES("volumes", 0.25, "space by leaf volume, log2 of the root's (total variation)"),
    /** Where the first levels' split planes lie across the root (mean total variation per level, the axes pooled). */
    SPLITS("splits", 0.25, "split positions in the first " + TreeSignature.SPLIT_DEPTHS + " levels, axes pooled (mean total variation)"),
    /** How deep the leaves are (total variation of the depth profiles). */
    DEPTHS("depths", 0.25, "leaves per depth (total variation)"),
    /** Where deep leaves are: the leaf-depth pictures on the common grid (weighted Jaccard distance). */
    OCCUPANCY("occupancy", 0.25, "leaf depth per cell of the common grid (1 - sum min / sum max)");

    private final String label;
    private final double weight;
    private final String help;

    Term(String label, double weight, String help) {
        this.label = label;
        this.weight = weight;
        this.help = help;
    }

    /** {@return the term's name, as the command line prints it} */
    public String label() { return label; }

    /** {@return the term's share of the total distance} */
    public double weight() { return weight; }

    /** {@return what the term compares, in one line} */
    public String help() { return help; }
}
