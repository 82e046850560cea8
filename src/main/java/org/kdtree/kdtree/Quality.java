package org.kdtree.kdtree;

/**
 * Named SAH settings along the measured trade-off between build time and tree quality
 * (docs/sah.md, "Quality presets"). What they give up, measured on the meshes: near the
 * leaves the greedy SAH goes on cutting a few triangles apart, each cut saving a little, and
 * those nodes are most of the tree and most of the build. Stopping at a few references
 * ({@link SahBuilder#leafBelow}) removes them for little loss.
 */
public enum Quality {
    /**
     * The exact event algorithm, leaves below 11 references: chosen by the study of docs/sah.md
     * ("Quality presets": four meshes, 1, 10 and 100 rays per triangle, build plus trace time) over
     * the binned searches, which built no faster once the small nodes they sweep exactly are
     * counted; 13 to 18 % of the exact tree's nodes, within 25 % of its expected cost.
     */
    FAST(SahBuilder.Algorithm.EVENT, -1, 11),
    /**
     * The exact event algorithm, leaves below 6 references: on the meshes measured, 35 to 45 % of
     * the exact tree's nodes, within 4 % of its expected cost.
     */
    BALANCED(SahBuilder.Algorithm.EVENT, -1, 6),
    /** The exact SAH tree (event algorithm), every split that pays. */
    EXACT(SahBuilder.Algorithm.EVENT, -1, 1);

    private final SahBuilder.Algorithm algorithm;
    /** The binned search's exact threshold; -1 (an exact search, which does not read it) restores the setting's default. */
    private final int exactBelow, leafBelow;

    Quality(SahBuilder.Algorithm algorithm, int exactBelow, int leafBelow) {
        this.algorithm = algorithm;
        this.exactBelow = exactBelow;
        this.leafBelow = leafBelow;
    }

    /** {@return the plane search of this preset} */
    public SahBuilder.Algorithm algorithm() { return algorithm; }

    /** {@return what the preset sets, in a few words}, e.g. for the command line's help */
    public String describe() {
        return (algorithm.exact() ? "exact, " : "binned, exact below " + exactBelow + ", ")
                + (leafBelow <= 1 ? "no leaf without a plane search" : "leaves below " + leafBelow + " references");
    }

    /** {@return the node size below which this preset makes leaves without a plane search} */
    public int leafBelow() { return leafBelow; }

    /** {@return the binned search's exact threshold, or -1 where the preset leaves it at the setting's default} */
    public int exactBelow() { return exactBelow; }
}
