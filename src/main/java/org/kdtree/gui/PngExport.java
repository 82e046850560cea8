package org.kdtree.gui;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.kdtree.files.AtomicFile;

/** Writes a canvas snapshot as a PNG file. */
final class PngExport {
    private PngExport() {
    }

    /**
     * Writes {@code image} as a PNG file.
     *
     * @param image the picture
     * @param file the PNG file, replaced whole if it exists ({@link AtomicFile})
     * @throws IOException if writing fails; the file is then left as it was
     */
    public static void write(BufferedImage image, Path file) throws IOException {
        AtomicFile.write(file, out -> {
            if (!ImageIO.write(image, "png", out)) throw new IOException("no PNG writer available");
        });
    }
}
