package org.jecosys.render.gl;

import static org.lwjgl.opengl.GL11C.GL_PACK_ALIGNMENT;
import static org.lwjgl.opengl.GL11C.GL_RGBA;
import static org.lwjgl.opengl.GL11C.GL_UNSIGNED_BYTE;
import static org.lwjgl.opengl.GL11C.glPixelStorei;
import static org.lwjgl.opengl.GL11C.glReadPixels;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import org.lwjgl.stb.STBImageWrite;
import org.lwjgl.system.MemoryUtil;

/**
 * Reading the bound framebuffer back and writing PNG files (stb_image_write): headless rendering,
 * screenshots and tests. Pixels are RGBA8, rows bottom-up as GL returns them.
 */
public final class Pixels {
    private Pixels() {
    }

    /**
     * Reads {@code width x height} RGBA pixels of the bound read framebuffer into {@code dest} (at
     * least {@code 4 * width * height} bytes; rows bottom-up). Render thread; no allocation.
     *
     * @param width  pixels, from the left edge
     * @param height pixels, from the bottom edge
     * @param dest   receives the pixels from index 0; cleared first (position 0, limit capacity)
     * @throws IllegalArgumentException when {@code dest} is too small
     */
    public static void read(int width, int height, ByteBuffer dest) {
        if (dest.capacity() < 4L * width * height) {
            throw new IllegalArgumentException("dest holds " + dest.capacity() + " bytes, needs " + 4L * width * height);
        }
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        dest.clear();
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, dest);
    }

    /**
     * {@return the red of pixel (x, y) in an RGBA buffer, 0-255}
     *
     * @param rgba  pixels as {@link #read} leaves them
     * @param width columns per row
     * @param x     column, from the left
     * @param y     row, from the bottom
     */
    public static int red(ByteBuffer rgba, int width, int x, int y) {
        return rgba.get(4 * (y * width + x)) & 255;
    }

    /**
     * {@return the green of pixel (x, y) in an RGBA buffer, 0-255}
     *
     * @param rgba  pixels as {@link #read} leaves them
     * @param width columns per row
     * @param x     column, from the left
     * @param y     row, from the bottom
     */
    public static int green(ByteBuffer rgba, int width, int x, int y) {
        return rgba.get(4 * (y * width + x) + 1) & 255;
    }

    /**
     * {@return the blue of pixel (x, y) in an RGBA buffer, 0-255}
     *
     * @param rgba  pixels as {@link #read} leaves them
     * @param width columns per row
     * @param x     column, from the left
     * @param y     row, from the bottom
     */
    public static int blue(ByteBuffer rgba, int width, int x, int y) {
        return rgba.get(4 * (y * width + x) + 2) & 255;
    }

    /**
     * Writes bottom-up RGBA pixels as a PNG file (top row first), creating parent folders; opaque
     * (alpha forced to 255). Any thread; allocates a native buffer for the flipped copy.
     *
     * @param file   the PNG to write (replaced if it exists)
     * @param rgba   {@code 4 * width * height} bytes, rows bottom-up
     * @param width  pixels
     * @param height pixels
     * @throws IOException when the folder or the file cannot be written
     */
    public static void writePng(Path file, ByteBuffer rgba, int width, int height) throws IOException {
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        int row = 4 * width;
        ByteBuffer flipped = MemoryUtil.memAlloc(row * height);
        try {
            for (int y = 0; y < height; y++) {
                int src = (height - 1 - y) * row;
                for (int i = 0; i < row; i++) {
                    flipped.put(y * row + i, (i & 3) == 3 ? (byte) 255 : rgba.get(src + i));
                }
            }
            if (!STBImageWrite.stbi_write_png(file.toString(), width, height, 4, flipped, row)) {
                throw new IOException("cannot write PNG " + file);
            }
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) flipped);
        }
    }
}
