package org.kdtree.render;

import java.awt.image.BufferedImage;

/** Linear RGB radiance per pixel, row by row from the top-left. */
public final class Image {
    private final int width, height;
    private final float[] rgb;

    /**
     * A black image.
     *
     * @param width width in pixels
     * @param height height in pixels
     */
    public Image(int width, int height) {
        this.width = width;
        this.height = height;
        this.rgb = new float[3 * width * height];
    }

    /** {@return the width in pixels} */
    public int width() { return width; }
    /** {@return the height in pixels} */
    public int height() { return height; }

    /**
     * Sets pixel (x, y) to a radiance.
     *
     * @param x the column, from the left
     * @param y the row, from the top
     * @param r the linear red radiance
     * @param g the linear green radiance
     * @param b the linear blue radiance
     */
    public void set(int x, int y, double r, double g, double b) {
        int i = 3 * (y * width + x);
        rgb[i] = (float) r;
        rgb[i + 1] = (float) g;
        rgb[i + 2] = (float) b;
    }

    /**
     * {@return channel {@code c} (0 red, 1 green, 2 blue) of pixel (x, y)}
     *
     * @param x the column, from the left
     * @param y the row, from the top
     * @param c the channel
     */
    public float get(int x, int y, int c) { return rgb[3 * (y * width + x) + c]; }

    /** {@return whether any channel of any pixel is NaN, infinite or negative}: never for a correct render. */
    public boolean hasInvalidPixels() {
        for (float v : rgb) if (!(v >= 0) || Float.isInfinite(v)) return true;
        return false;
    }

    /** {@return the image in 8-bit sRGB (gamma 2.2, clamped)}, as written to PNG. */
    public BufferedImage toBufferedImage() {
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++)
            for (int x = 0; x < width; x++)
                img.setRGB(x, y, (toByte(get(x, y, 0)) << 16) | (toByte(get(x, y, 1)) << 8) | toByte(get(x, y, 2)));
        return img;
    }

    private static int toByte(float linear) {
        double v = Math.pow(Math.max(0, Math.min(1, linear)), 1 / 2.2);
        return (int) Math.round(255 * v);
    }

    /**
     * Writes the image as PNG.
     *
     * @param file the PNG file, replaced whole if it exists ({@link org.kdtree.files.AtomicFile}); missing folders are made
     * @throws java.io.IOException if writing fails; the file is then left as it was
     */
    public void writePng(java.nio.file.Path file) throws java.io.IOException {
        java.nio.file.Path parent = file.toAbsolutePath().getParent();
        if (parent != null) java.nio.file.Files.createDirectories(parent);
        java.awt.image.BufferedImage picture = toBufferedImage();
        org.kdtree.files.AtomicFile.write(file, out -> {
            if (!javax.imageio.ImageIO.write(picture, "png", out))
                throw new java.io.IOException(file + ": no PNG writer available");
        });
    }
}
