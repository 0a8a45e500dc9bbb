package org.jecosys.terrain;

import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.io.IOException;
import javax.imageio.ImageIO;
import org.jecosys.math.Require;

/**
 * A greyscale image read from a PNG (or any format {@link ImageIO} reads) as levels in [0, 1],
 * row 0 first. Single-band images (8 or 16 bit grey) keep their full precision; colour images are
 * reduced to Rec. 709 luminance. Package-private helper for heightmaps and IMAGE resource maps.
 * Immutable after construction; any thread may read it.
 */
final class GreyImage {
    final int width;
    final int height;
    /** Levels in [0, 1], index {@code row * width + column}. */
    final float[] levels;

    private GreyImage(int width, int height, float[] levels) {
        this.width = width;
        this.height = height;
        this.levels = levels;
    }

    /** Share of the free heap one image may take while it is decoded. */
    static final double HEAP_SHARE = 0.8;

    /**
     * Reads the image {@code path} from {@code images} and decodes those same bytes: the size from
     * the header is bounded by {@link ImageFiles#MAX_SIDE} and by the heap free now before anything is
     * decoded, so an image swapped for a larger one after the scene was checked is refused, never
     * an OutOfMemoryError.
     *
     * @param name   argument name used in error messages ("heightmap", "image")
     * @param images where the image comes from
     * @param path   the path as the scene writes it
     * @throws IOException              naming the image when it cannot be read or decoded, a side is
     *                                  above {@link ImageFiles#MAX_SIDE}, or decoding it needs more
     *                                  memory than the heap has free
     * @throws IllegalArgumentException when an argument is null or the file is not an image
     */
    static GreyImage read(String name, ImageSource images, String path) throws IOException {
        Require.nonNull(name, path);
        Require.nonNull("images", images);
        byte[] bytes = images.read(path);
        String label = "'" + path + "'";
        ImageFiles.Size size;
        try {
            size = ImageFiles.header(label, bytes); // the size is bounded before anything is decoded
        } catch (ImageFiles.NotAnImage e) {
            throw new IllegalArgumentException(name + " is not an image ImageIO can read: " + path, e);
        }
        Runtime rt = Runtime.getRuntime();
        long free = rt.maxMemory() - (rt.totalMemory() - rt.freeMemory());
        if (size.bytes() > HEAP_SHARE * free) {
            throw new IOException("image " + label + " is " + size.width() + " x " + size.height()
                    + " pixels: decoding it needs about " + (size.bytes() >> 20) + " MiB, more than the "
                    + (long) (HEAP_SHARE * free) / (1 << 20) + " MiB the Java heap has free (set it with -Xmx; "
                    + "was the file replaced after the scene was checked?)");
        }
        BufferedImage img;
        try {
            img = ImageIO.read(ImageFiles.stream(bytes)); // closes the stream
        } catch (IOException e) {
            throw ImageFiles.named(label, e);
        } catch (RuntimeException e) {
            throw new IOException("image " + label + ": cannot decode its data (" + e + ")", e);
        }
        if (img == null) {
            throw new IllegalArgumentException(name + " is not an image ImageIO can read: " + path);
        }
        int w = img.getWidth();
        int h = img.getHeight();
        float[] levels = new float[w * h];
        Raster raster = img.getRaster();
        boolean grey = raster.getNumBands() == 1 && img.getColorModel().getNumComponents() == 1;
        if (grey) {
            int bits = img.getColorModel().getComponentSize(0);
            double max = (1L << bits) - 1;
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    levels[y * w + x] = (float) (raster.getSample(x, y, 0) / max);
                }
            }
        } else {
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    int rgb = img.getRGB(x, y);
                    double r = (rgb >>> 16) & 0xFF;
                    double g = (rgb >>> 8) & 0xFF;
                    double b = rgb & 0xFF;
                    levels[y * w + x] = (float) ((0.2126 * r + 0.7152 * g + 0.0722 * b) / 255.0);
                }
            }
        }
        return new GreyImage(w, h, levels);
    }

    /**
     * Bilinear level at fractional pixel coordinates (u along columns, v along rows, pixel centres
     * at integers), clamped to the image.
     */
    double sample(double u, double v) {
        u = Math.max(0, Math.min(width - 1, u));
        v = Math.max(0, Math.min(height - 1, v));
        int x0 = Math.min((int) u, Math.max(0, width - 2));
        int y0 = Math.min((int) v, Math.max(0, height - 2));
        int x1 = Math.min(x0 + 1, width - 1);
        int y1 = Math.min(y0 + 1, height - 1);
        double fx = u - x0;
        double fy = v - y0;
        double a = levels[y0 * width + x0] + (levels[y0 * width + x1] - levels[y0 * width + x0]) * fx;
        double b = levels[y1 * width + x0] + (levels[y1 * width + x1] - levels[y1 * width + x0]) * fx;
        return a + (b - a) * fy;
    }
}
