package org.kdtree.treefile;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import org.kdtree.accel.AccelerationStructure;
import org.kdtree.shape.Primitives;
import org.kdtree.spec.BuilderSpec;

/** The tests' round trip: a structure saved to bytes and read back over the same primitives. */
final class Saved {
    private Saved() {
    }

    /** {@return the bytes of {@code tree}'s file} */
    static byte[] bytes(AccelerationStructure tree, BuilderSpec spec, Primitives primitives) {
        try {
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            TreeFile.write(out, tree, spec, primitives);
            return out.toByteArray();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** {@return the tree of {@code bytes} over {@code primitives}} */
    static SavedTree read(byte[] bytes, Primitives primitives) throws IOException {
        return TreeFile.read(new ByteArrayInputStream(bytes), "test.kdtree", primitives);
    }

    /** {@return {@code spec}'s structure over {@code primitives}, saved and loaded again} */
    static AccelerationStructure roundTrip(BuilderSpec spec, Primitives primitives) {
        try {
            return read(bytes(spec.build(primitives, null), spec, primitives), primitives).structure();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
