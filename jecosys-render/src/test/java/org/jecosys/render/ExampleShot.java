package org.jecosys.render;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;

/**
 * The screenshot of an engine example's test mode and what the example printed about it, one
 * {@code TAG probe ...} line each (image coordinates, origin top left): {@code probe hud x0 y0 x1 y1}
 * (the HUD text's box), {@code probe ground x y} (bare ground: no plant within 1.3 m),
 * {@code probe plant x y} (a plant just above its base), {@code probe player x y},
 * {@code bend near N far F} (mean bend of the plants within 1 m of the player and 3 to 6 m from it),
 * optionally {@code draw allocations: K of N frames, ...} (frames whose plant drawing allocated on the
 * render thread), {@code gl errors: none} or a count, and a {@code GL error ...} line per error found.
 */
public final class ExampleShot {
    /** Plant green: green well above red and blue. */
    public static boolean plant(int rgb) {
        int r = rgb >> 16 & 255;
        int g = rgb >> 8 & 255;
        int b = rgb & 255;
        return g > r + 8 && g > b + 8;
    }

    /** The examples' soil: red over green over blue, warm. */
    public static boolean soil(int rgb) {
        int r = rgb >> 16 & 255;
        int g = rgb >> 8 & 255;
        int b = rgb & 255;
        return r > g && g > b && r - b > 25;
    }

    /** The examples' HUD text: a bright yellow. */
    public static boolean hudText(int rgb) {
        int r = rgb >> 16 & 255;
        int g = rgb >> 8 & 255;
        int b = rgb & 255;
        return r > 180 && g > 140 && b < 130 && r - b > 100;
    }

    /** The examples' player: a saturated blue. */
    public static boolean player(int rgb) {
        int r = rgb >> 16 & 255;
        int g = rgb >> 8 & 255;
        int b = rgb & 255;
        return b > r + 60 && b > g + 30;
    }

    /** A colour class of pixels. */
    @FunctionalInterface
    public interface Colour {
        /**
         * Whether a pixel is of this class.
         *
         * @param rgb 0xRRGGBB
         * @return true when it is
         */
        boolean test(int rgb);
    }

    private final BufferedImage image;
    private final String output;
    private final int[] hud;
    private final int[] ground;
    private final int[] player;
    private final List<int[]> plants = new ArrayList<>();
    private final double bendNear;
    private final double bendFar;
    private final int[] drawAllocations;

    private ExampleShot(BufferedImage image, String output, String tag) {
        this.image = image;
        this.output = output;
        int[] h = null;
        int[] g = null;
        int[] pl = null;
        double near = Double.NaN;
        double far = Double.NaN;
        int[] alloc = null;
        for (String line : output.split("\n")) {
            if (!line.startsWith(tag)) {
                continue;
            }
            String[] w = line.substring(tag.length()).trim().split("\\s+");
            if (w[0].equals("probe") && w.length >= 4) {
                int[] v = new int[w.length - 2];
                for (int i = 2; i < w.length; i++) {
                    v[i - 2] = Integer.parseInt(w[i]);
                }
                switch (w[1]) {
                    case "hud" -> h = v;
                    case "ground" -> g = v;
                    case "player" -> pl = v;
                    case "plant" -> plants.add(v);
                    default -> { }
                }
            } else if (w[0].equals("bend") && w.length == 5) {
                near = Double.parseDouble(w[2]);
                far = Double.parseDouble(w[4]);
            } else if (w[0].equals("draw") && w[1].equals("allocations:") && w.length >= 5) {
                alloc = new int[] {Integer.parseInt(w[2]), Integer.parseInt(w[4])};
            }
        }
        hud = h;
        ground = g;
        player = pl;
        bendNear = near;
        bendFar = far;
        drawAllocations = alloc;
    }

    /**
     * Reads the screenshot and the probe lines.
     *
     * @param png    the screenshot
     * @param output what the example printed
     * @param tag    its line prefix, e.g. {@code "[gdx-meadow]"}
     * @return the shot
     * @throws IOException when the PNG cannot be read
     */
    public static ExampleShot read(Path png, String output, String tag) throws IOException {
        BufferedImage img = ImageIO.read(png.toFile());
        if (img == null) {
            throw new IOException(png + " is not an image");
        }
        return new ExampleShot(img, output, tag);
    }

    /** {@return the image} */
    public BufferedImage image() {
        return image;
    }

    /** {@return whether the example reported "gl errors: none" and no GL error line} */
    public boolean noGlErrors() {
        return output.contains("gl errors: none") && !output.contains("GL error");
    }

    /** {@return the HUD text box x0, y0, x1, y1, or null when not reported} */
    public int[] hud() {
        return hud;
    }

    /** {@return the bare ground point, or null when the example found none} */
    public int[] ground() {
        return ground;
    }

    /** {@return the player's point, or null} */
    public int[] player() {
        return player;
    }

    /** {@return the plant points} */
    public List<int[]> plants() {
        return plants;
    }

    /** {@return the mean bend within 1 m of the player} */
    public double bendNear() {
        return bendNear;
    }

    /** {@return the mean bend 3 to 6 m from the player} */
    public double bendFar() {
        return bendFar;
    }

    /**
     * What the examples' tests check, each with its measurement: no GL error; the HUD text in its box
     * (at least 40 text pixels); bare ground in the engine's soil colour (60% of an 11 x 11 square);
     * at least 6 plants, three quarters of them plant green (20% of a 9 x 9 square); the player in
     * its blue; the plants near the player bent (mean over 0.3, and over twice the bend 3 to 6 m away:
     * the trail it pushes through the grass); where reported, drawing the plants allocating in at most
     * a quarter of the frames measured.
     *
     * @return the failed checks, empty when all pass
     */
    public List<String> problems() {
        List<String> bad = new ArrayList<>();
        if (!noGlErrors()) {
            bad.add("GL errors reported (or no 'gl errors: none' line)");
        }
        if (hud == null) {
            bad.add("no HUD probe");
        } else {
            int text = count(ExampleShot::hudText, hud[0], hud[1], hud[2], hud[3]);
            if (text < 40) {
                bad.add("HUD text pixels in " + hud[0] + "," + hud[1] + " to " + hud[2] + "," + hud[3] + ": " + text);
            }
        }
        if (ground == null) {
            bad.add("no bare ground probe");
        } else if (share(ExampleShot::soil, ground, 5) < 0.6) {
            bad.add("soil share at the bare ground " + ground[0] + "," + ground[1] + ": "
                    + share(ExampleShot::soil, ground, 5));
        }
        int green = 0;
        for (int[] p : plants) {
            if (share(ExampleShot::plant, p, 4) >= 0.2) {
                green++;
            }
        }
        if (plants.size() < 6 || green < 0.75 * plants.size()) {
            bad.add("plant probes that show plant green: " + green + " of " + plants.size());
        }
        if (player == null || share(ExampleShot::player, player, 3) < 0.6) {
            bad.add("the player's blue at " + (player == null ? "?" : player[0] + "," + player[1]));
        }
        if (!(bendNear > 0.3 && bendNear > 2 * bendFar)) {
            bad.add("bend near the player " + bendNear + " vs 3 to 6 m away " + bendFar);
        }
        // an allocation per frame shows in every frame; the JIT may allocate now and then on its own
        if (drawAllocations != null && (drawAllocations[1] < 10 || drawAllocations[0] > drawAllocations[1] / 4)) {
            bad.add("frames whose plant drawing allocated: " + drawAllocations[0] + " of " + drawAllocations[1]);
        }
        return bad;
    }

    /**
     * Counts the pixels of a class in a box (clipped to the image).
     *
     * @param colour the class
     * @param x0     left, inclusive
     * @param y0     top, inclusive
     * @param x1     right, exclusive
     * @param y1     bottom, exclusive
     * @return the count
     */
    public int count(Colour colour, int x0, int y0, int x1, int y1) {
        int n = 0;
        for (int y = Math.max(0, y0); y < Math.min(image.getHeight(), y1); y++) {
            for (int x = Math.max(0, x0); x < Math.min(image.getWidth(), x1); x++) {
                if (colour.test(image.getRGB(x, y) & 0xFFFFFF)) {
                    n++;
                }
            }
        }
        return n;
    }

    /**
     * The share of a class among the pixels of the square of side {@code 2 r + 1} around a point.
     *
     * @param colour the class
     * @param p      the point (x, y)
     * @param r      the half side, pixels
     * @return the share, in [0, 1]
     */
    public double share(Colour colour, int[] p, int r) {
        int x0 = Math.max(0, p[0] - r);
        int y0 = Math.max(0, p[1] - r);
        int x1 = Math.min(image.getWidth(), p[0] + r + 1);
        int y1 = Math.min(image.getHeight(), p[1] + r + 1);
        return count(colour, x0, y0, x1, y1) / (double) Math.max(1, (x1 - x0) * (y1 - y0));
    }

    /**
     * The median of each channel over the pixels of a class in the squares around the given points.
     *
     * @param colour the class
     * @param points the points
     * @param r      the squares' half side
     * @return {r, g, b} medians, or null when no pixel is of the class
     */
    public int[] median(Colour colour, List<int[]> points, int r) {
        List<Integer> rs = new ArrayList<>();
        List<Integer> gs = new ArrayList<>();
        List<Integer> bs = new ArrayList<>();
        for (int[] p : points) {
            for (int y = Math.max(0, p[1] - r); y <= Math.min(image.getHeight() - 1, p[1] + r); y++) {
                for (int x = Math.max(0, p[0] - r); x <= Math.min(image.getWidth() - 1, p[0] + r); x++) {
                    int rgb = image.getRGB(x, y) & 0xFFFFFF;
                    if (colour.test(rgb)) {
                        rs.add(rgb >> 16 & 255);
                        gs.add(rgb >> 8 & 255);
                        bs.add(rgb & 255);
                    }
                }
            }
        }
        if (rs.isEmpty()) {
            return null;
        }
        rs.sort(null);
        gs.sort(null);
        bs.sort(null);
        int m = rs.size() / 2;
        return new int[] {rs.get(m), gs.get(m), bs.get(m)};
    }
}
