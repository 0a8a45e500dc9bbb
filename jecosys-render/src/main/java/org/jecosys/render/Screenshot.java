package org.jecosys.render;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import org.jecosys.render.gl.Pixels;

/**
 * Reading back what was drawn, for a game's screenshots and image tests: the bound read framebuffer
 * as RGBA8 bytes (rows bottom-up, as OpenGL returns them) and those bytes as a PNG file.
 * {@link #writePng} needs LWJGL's {@code lwjgl-stb} (and its natives) on the class path, which
 * {@code jecosys-render} does not bring to a game; {@link #read} needs nothing more than OpenGL.
 */
public final class Screenshot {
    private Screenshot() {
    }

    /**
     * Reads {@code width x height} RGBA pixels of the bound read framebuffer (from its lower-left
     * corner) into {@code dest}. Render thread, with the GL context current; no allocation.
     *
     * @param width  pixels, at least 1
     * @param height pixels, at least 1
     * @param dest   at least {@code 4 * width * height} bytes; receives the pixels from index 0, rows
     *               bottom-up; its position is set to 0 and its limit to its capacity
     * @throws IllegalArgumentException when a size is below 1 or {@code dest} is too small
     */
    public static void read(int width, int height, ByteBuffer dest) {
        requireSize(width, height);
        if (dest == null) {
            throw new IllegalArgumentException("dest is null; allocate 4 * width * height bytes");
        }
        Pixels.read(width, height, dest);
    }

    /**
     * Writes RGBA pixels, rows bottom-up as {@link #read} leaves them, as an opaque PNG file (top row
     * first, alpha written as 255), creating missing parent folders and replacing the file. Any thread;
     * allocates a native copy of the pixels for the duration of the call.
     *
     * @param file   the PNG to write
     * @param rgba   {@code 4 * width * height} bytes from index 0
     * @param width  pixels, at least 1
     * @param height pixels, at least 1
     * @throws IllegalArgumentException when a size is below 1 or {@code rgba} is too small
     * @throws IOException              when the folder or the file cannot be written
     */
    public static void writePng(Path file, ByteBuffer rgba, int width, int height) throws IOException {
        requireSize(width, height);
        if (file == null || rgba == null) {
            throw new IllegalArgumentException("file and rgba must not be null");
        }
        if (rgba.capacity() < 4L * width * height) {
            throw new IllegalArgumentException("rgba holds " + rgba.capacity() + " bytes; " + width + " x " + height
                    + " pixels need " + 4L * width * height);
        }
        Pixels.writePng(file, rgba, width, height);
    }

    private static void requireSize(int width, int height) {
        if (width < 1 || height < 1 || 4L * width * height > Integer.MAX_VALUE) {
            throw new IllegalArgumentException("size " + width + " x " + height
                    + ": width and height must be at least 1 and 4 * width * height at most " + Integer.MAX_VALUE);
        }
    }
}
