import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.util.Random;
import javax.imageio.ImageIO;

/**
 * Makes the textures of scenes/textured.xml, deterministically: java scenes/textures/MakeTextures.java scenes/textures
 *
 * The images are detail maps: near-white values (veins, a midrib, edges, a gradient) with an alpha
 * outline; the scene's component colour tints them, so a species' colour and its per-plant variation
 * still apply. Rows from the top of the image are the tip of a strip; a fan's image is centred.
 * Part of JEcoSys, under the project's licence.
 */
public final class MakeTextures {
    private MakeTextures() {
    }

    public static void main(String[] args) throws IOException {
        File out = new File(args.length > 0 ? args[0] : ".");
        out.mkdirs();
        ImageIO.write(blade(), "png", new File(out, "grass-blade.png"));
        ImageIO.write(petal(), "png", new File(out, "petal.png"));
        ImageIO.write(head(), "png", new File(out, "flower-head.png"));
    }

    private static int argb(double a, double r, double g, double b) {
        return (clamp(a) << 24) | (clamp(r) << 16) | (clamp(g) << 8) | clamp(b);
    }

    private static int clamp(double v) {
        return (int) Math.round(Math.max(0, Math.min(1, v)) * 255);
    }

    private static double smooth(double e0, double e1, double x) {
        double t = Math.max(0, Math.min(1, (x - e0) / (e1 - e0)));
        return t * t * (3 - 2 * t);
    }

    /** A grass blade, 32 x 128: a pale midrib, fine parallel veins, darker edges, a pointed tip outline. */
    static BufferedImage blade() {
        int w = 32;
        int h = 128;
        Random rnd = new Random(40);
        double[] vein = new double[w];
        for (int x = 0; x < w; x++) {
            vein[x] = 0.025 * rnd.nextGaussian();
        }
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_ARGB);
        for (int y = 0; y < h; y++) {
            double v = 1 - (y + 0.5) / h;                  // 0 at the base (bottom row), 1 at the tip
            double half = 0.5 * (1 - smooth(0.72, 1.0, v)); // the outline narrows to a point over the last 28%
            for (int x = 0; x < w; x++) {
                double u = (x + 0.5) / w - 0.5;            // -0.5 to 0.5 across
                double edge = Math.abs(u) / Math.max(half, 1e-3);
                double alpha = 1 - smooth(0.86, 1.0, edge);
                double midrib = 0.08 * Math.exp(-u * u / 0.002);
                double veins = 0.035 * Math.cos(u * Math.PI * 18) + vein[x];
                double value = 0.95 + midrib + veins - 0.12 * edge * edge + 0.03 * v;
                img.setRGB(x, y, argb(alpha, value * 0.98, value, value * 0.94));
            }
        }
        return img;
    }

    /** A petal, 64 x 64: rounded outline, veins from the base, warmer toward the base. */
    static BufferedImage petal() {
        int s = 64;
        BufferedImage img = new BufferedImage(s, s, BufferedImage.TYPE_INT_ARGB);
        for (int y = 0; y < s; y++) {
            double v = 1 - (y + 0.5) / s;
            // widest at two thirds, rounded at the tip, narrow at the base
            double half = 0.5 * Math.sqrt(Math.max(0, Math.sin(Math.PI * Math.min(1, v * 0.75 + 0.05))));
            for (int x = 0; x < s; x++) {
                double u = (x + 0.5) / s - 0.5;
                double edge = Math.abs(u) / Math.max(half, 1e-3);
                double alpha = 1 - smooth(0.88, 1.0, edge);
                double veins = 0.07 * Math.cos(Math.atan2(u, v + 0.05) * 22);
                double value = 0.97 + veins * v - 0.08 * edge * edge;
                double warm = 1 - smooth(0.0, 0.3, v);      // toward orange at the base
                img.setRGB(x, y, argb(alpha, value, value * (1 - 0.18 * warm), value * (1 - 0.5 * warm)));
            }
        }
        return img;
    }

    /** A flower head seen from above, 64 x 64: a disc of seeds in a spiral, darker in the middle. */
    static BufferedImage head() {
        int s = 64;
        BufferedImage img = new BufferedImage(s, s, BufferedImage.TYPE_INT_ARGB);
        double golden = Math.PI * (3 - Math.sqrt(5));
        for (int y = 0; y < s; y++) {
            for (int x = 0; x < s; x++) {
                double dx = (x + 0.5) / s - 0.5;
                double dy = (y + 0.5) / s - 0.5;
                double r = Math.hypot(dx, dy) / 0.5;
                double alpha = 1 - smooth(0.9, 1.0, r);
                // the nearest seed of a Fermat spiral of 160 seeds
                double best = 1e9;
                for (int k = 0; k < 160; k++) {
                    double rr = 0.47 * Math.sqrt((k + 0.5) / 160);
                    double sx = rr * Math.cos(k * golden) - dx;
                    double sy = rr * Math.sin(k * golden) - dy;
                    best = Math.min(best, sx * sx + sy * sy);
                }
                double seed = Math.exp(-best / 0.0004);
                double value = (0.72 + 0.28 * r) * (0.85 + 0.2 * seed);
                img.setRGB(x, y, argb(alpha, value, value * 0.92, value * 0.8));
            }
        }
        return img;
    }
}
