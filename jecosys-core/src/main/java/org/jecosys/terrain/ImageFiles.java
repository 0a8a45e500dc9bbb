package org.jecosys.terrain;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.util.Iterator;
import javax.imageio.ImageIO;
import javax.imageio.ImageReadParam;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import javax.imageio.stream.MemoryCacheImageInputStream;
import org.jecosys.math.Require;

/**
 * Checks of the greyscale images a terrain reads (heightmaps and IMAGE resource maps, paper §4.3)
 * before they are decoded, on the bytes read once through an {@link ImageSource}: the size from the
 * header only, bounded by {@link #MAX_SIDE}, and a decoding pass at reduced resolution that finds
 * corrupt or truncated data without holding the full image. Every failure is an {@link IOException}
 * whose message names the image. Any thread; allocates (load time).
 */
public final class ImageFiles {
    /**
     * Most pixels along either side of an image. The heightfield has at most 2049 vertices and a
     * resource map 1024 cells per side, so larger images add nothing but memory.
     */
    public static final int MAX_SIDE = 8192;
    /** Heap bytes per pixel while an image is read: the decoded image (up to 8) and its levels (4). */
    public static final int BYTES_PER_PIXEL = 12;

    private ImageFiles() {
    }

    /**
     * The size of an image, from its header only (nothing is decoded).
     *
     * @param width  pixels per row, &gt;= 1
     * @param height rows, &gt;= 1
     */
    public record Size(int width, int height) {
        /**
         * Checks the size.
         *
         * @param width  pixels per row, &gt;= 1
         * @param height rows, &gt;= 1
         * @throws IllegalArgumentException when a side is below 1
         */
        public Size {
            Require.range("width", width, 1, Integer.MAX_VALUE);
            Require.range("height", height, 1, Integer.MAX_VALUE);
        }

        /** {@return the heap bytes reading the image takes, {@link #BYTES_PER_PIXEL} per pixel} */
        public long bytes() {
            return (long) width * height * BYTES_PER_PIXEL;
        }
    }

    /**
     * Reads an image's size from its header and checks it against {@link #MAX_SIDE}, before anything
     * is decoded. Any thread; allocates a little.
     *
     * @param name  the image's name for messages (the path the scene writes)
     * @param bytes the whole image file
     * @return its size
     * @throws IOException naming the image when it is not an image ImageIO reads ({@link NotAnImage})
     *                     or has a side above {@link #MAX_SIDE}
     */
    public static Size header(String name, byte[] bytes) throws IOException {
        Require.nonNull("name", name);
        Require.nonNull("bytes", bytes);
        try (ImageInputStream in = stream(bytes)) {
            ImageReader reader = reader(in, name);
            try {
                int w = reader.getWidth(0);
                int h = reader.getHeight(0);
                if (w < 1 || h < 1 || w > MAX_SIDE || h > MAX_SIDE) {
                    throw new IOException("image " + name + " is " + w + " x " + h + " pixels; images are limited to "
                            + MAX_SIDE + " pixels a side (ImageFiles.MAX_SIDE)");
                }
                return new Size(w, h);
            } finally {
                reader.dispose();
            }
        } catch (IOException e) {
            throw named(name, e);
        } catch (RuntimeException e) {
            throw new IOException("image " + name + ": cannot read its header (" + e + ")", e);
        }
    }

    /**
     * Decodes the whole image at a reduced resolution (every 8th pixel of every 8th row: all the
     * compressed data is read, 1/64 of the pixels kept), so that corrupt or truncated data is found
     * before a scene is accepted, without holding the full image. Checks the header first
     * ({@link #header}). Any thread; allocates at most a 64th of the image.
     *
     * @param name  the image's name for messages (the path the scene writes)
     * @param bytes the whole image file
     * @return its size
     * @throws IOException naming the image when the header or the data cannot be read
     */
    public static Size verify(String name, byte[] bytes) throws IOException {
        Size size = header(name, bytes);
        try (ImageInputStream in = stream(bytes)) {
            ImageReader reader = reader(in, name);
            try {
                ImageReadParam p = reader.getDefaultReadParam();
                p.setSourceSubsampling(8, 8, 0, 0);
                reader.read(0, p);
            } finally {
                reader.dispose();
            }
        } catch (IOException e) {
            throw named(name, e);
        } catch (RuntimeException e) {
            throw new IOException("image " + name + ": cannot decode its data (" + e + ")", e);
        }
        return size;
    }

    /** An image stream over bytes in memory (no cache file: ImageIO's default may write one). */
    static ImageInputStream stream(byte[] bytes) throws IOException {
        return new MemoryCacheImageInputStream(new ByteArrayInputStream(bytes));
    }

    static ImageReader reader(ImageInputStream in, String file) throws IOException {
        Iterator<ImageReader> readers = ImageIO.getImageReaders(in);
        if (!readers.hasNext()) {
            throw new NotAnImage("image " + file + ": not an image format Java reads (use a greyscale PNG)");
        }
        ImageReader reader = readers.next();
        reader.setInput(in, true, true);
        return reader;
    }

    /** The file is not in any image format ImageIO reads. */
    static final class NotAnImage extends IOException {
        private static final long serialVersionUID = 1L;

        NotAnImage(String message) {
            super(message);
        }
    }

    /** An IOException whose message names the file (once). */
    static IOException named(String file, IOException e) {
        String m = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
        if (m.startsWith("image " + file)) {
            return e;
        }
        return new IOException("image " + file + ": cannot be read: " + m + " (truncated or corrupt?)", e);
    }
}
