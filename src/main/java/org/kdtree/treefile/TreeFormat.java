package org.kdtree.treefile;

/**
 * The layout of a tree file, version {@value #VERSION}, little-endian throughout
 * (docs/tree-files.md has it byte by byte): a fixed header of {@value #HEADER} bytes, the
 * statistics, the builder and its settings, the structure's arrays, and a CRC-32C of every byte
 * before it.
 */
final class TreeFormat {
    /** The first bytes of every tree file: not text (0x89), then "KDT", then a CR LF, a ^Z and a LF that a text transfer would change. */
    static final byte[] MAGIC = {(byte) 0x89, 'K', 'D', 'T', '\r', '\n', 0x1a, '\n'};
    /** The format this code writes and reads; a changed layout is a new version. */
    static final int VERSION = 1;
    /** The bytes of the fixed header: magic, version, structure, length, then the primitives' fingerprint and Kt, Ki. */
    static final int HEADER = 64;
    /** The bytes the reader needs to decide on format, version and length: magic, version, structure, length. */
    static final int PREFIX = 24;
    /** The bytes of the statistics after the header. */
    static final int STATS = 56;
    /** The bytes of the checksum that ends the file. */
    static final int CHECKSUM = 4;

    /** The structure field: a kd-tree or a bounding volume hierarchy. */
    static final int KD_TREE = 1, BVH = 2;

    private TreeFormat() {
    }

    /** {@return the structure field's value in words} */
    static String structure(int kind) {
        return kind == KD_TREE ? "a kd-tree" : kind == BVH ? "a bounding volume hierarchy" : "structure " + kind;
    }
}
