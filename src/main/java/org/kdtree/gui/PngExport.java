package org.kdtree.gui;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import javax.imageio.ImageIO;

/** Writes a canvas snapshot as a PNG file. */
final class PngExport {
    private PngExport() {
    }

    /**
     * Writes {@code image} as a PNG file.
     *
     * @param image the picture
     * @param file the PNG file, replaced if it exists
     * @throws IOException if writing fails
     */
    public static void write(BufferedImage image, Path file) throws IOException {
        if (!ImageIO.write(image, "png", file.toFile())) throw new IOException("no PNG writer available");
    }
}
