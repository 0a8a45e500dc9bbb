package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import org.jecosys.math.ViewCamera;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.scene.SceneDef;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.World;
import org.jecosys.terrain.Heightfield;
import org.joml.Matrix4f;
import org.joml.Vector2d;
import org.joml.Vector4f;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Issue 41's wind measure as the issue states it: the meadow in its own wind seen from 15 m up and
 * oblique (the camera of {@link FromAboveFlickerTest}), 150 frames at 480x270, 1/30 s of wind each.
 * <ul>
 * <li><b>Strength</b>: the temporal s.d. of the mean luma of 16x16 blocks (at least half vegetation
 * standing on the terrain: not the ground beyond it),
 * median over the blocks of the middle and of the far third of the vegetation's rows; the issue asks
 * 8/255 in both.</li>
 * <li><b>Every second</b>: the same median over the middle and far blocks within each window of one
 * second of frames (every start frame), its least; the issue asks 3/255.</li>
 * <li><b>Bands</b>: ground points on a 0.5 m lattice aligned with the gusts' travel (u along it, v
 * across), inside the terrain, seen in the middle and far thirds; each point's value is the mean luma
 * of the 3x3 pixels where it projects, less its own mean over the frames. Pooled over points and
 * frames, the correlation of two points a distance apart along u and along v; a pattern's length along
 * an axis is where that correlation falls to 0.5 (interpolated between lattice steps). The issue asks
 * the length across to be at least twice the length along. Perspective shortens the ground along the
 * view, so on its own the picture smooths the pattern more along whichever axis lies closer to the
 * view's direction: the figure is reported with the angle between the wind and the view.</li>
 * <li><b>Travel</b>: the pooled correlation of each point with the point 2 m downwind, that one
 * delayed by a lag; its peak gives a speed, which the issue asks within 20% of the mean wind's (taken
 * as the gusts' travel speed the simulation reports, {@code WindField.gustTravel}).</li>
 * </ul>
 * One frame is 1/30 s of wind, as the render command draws them ({@code ./jecosys render}: its
 * HeadlessRender.FRAME_DT): 150 frames are the 5 s over which the issue saw "pale mottles drift like
 * cloud shadows". (Until the meadow's wind was retuned this test stepped 1/60 s per frame, as
 * {@link WindSheenTest} does, and so watched only 2.5 s.) The meadow prewarms 1 s
 * ({@code <animation prewarm>}, two of its grasses' response times): its plants start still, at the
 * equilibrium of the wind, and without it the first second read 2.40, short of the 3. With the
 * meadow's wind as shipped (gusts 4 m along the wind and 6 times that across it, gustStrength 1.6,
 * turbulence 0.45) it reads middle 12.27/255, far 8.04, every 1 s window 3.31 at least (median 4.31),
 * bands 3.90 times longer across than along with the wind 60 degrees off the view, travel 4.62 m/s
 * against 4.00 (+15%; one frame of lag is 7%): issue 41's figures, which the assertions hold. (With
 * gusts 7 m along and gustStrength 1 the least window was the first, 1.42, and the others 2.0-2.6.)
 * Tagged {@code slow} (150 frames of the whole meadow): it runs in
 * {@code mvn -B verify -Pnightly}.
 */
@Tag("slow")
class GustsFromAboveTest {
    private static final int W = 480;
    private static final int H = 270;
    private static final int FRAMES = 150;
    private static final int BLOCK = 16;
    /** Lattice step of the ground points, metres. */
    private static final double STEP = 0.5;
    /** Lattice steps tried for the correlation lengths (up to 10 m). */
    private static final int MAX_OFFSET = 20;
    /** Metres between a point and its downwind partner in the travel measure. */
    private static final double TRAVEL = 2.0;
    private static final int MAX_LAG = 60;
    /** Scene seconds between frames: the render command's (its HeadlessRender.FRAME_DT). */
    private static final double FRAME_DT = 1.0 / 30;

    @Test
    void gustsRunOverTheMeadowAsBandsSeenFromFifteenMetresUp() {
        SceneDef def = RenderScenes.load("meadow.xml");
        World world = RenderScenes.build(def);
        Heightfield hf = world.terrain().heightfield();
        ViewCamera cam = Shots.fromAbove(hf, W, H);
        int bx = W / BLOCK;
        int by = H / BLOCK;
        double[][] blocks = new double[bx * by][FRAMES];
        boolean[] veg;
        Lattice lattice;
        double[][] values;
        double speed;
        double dt;
        double windAngle;
        int[] bandRows;
        try (Shots s = new Shots(world, RenderScenes.settings(def), W, H);
             Simulation sim = Simulation.of(world, def.simulationDef(), 2)) {
            Img bare = s.render(TestFrames.rest(world, cam), cam, false, true);
            Img full = s.render(TestFrames.rest(world, cam), cam, true, true);
            veg = ImageMetrics.differ(full, bare, 6);
            // the meadow's rows: up to the highest row a ground point inside the terrain reaches (above it the
            // ground beyond the terrain, which has no plants)
            Lattice all = lattice(hf, cam, veg, 0, H, 1, 0);
            int top = 0;
            boolean[] inside = new boolean[W * H];
            for (int k = 0; k < all.count; k++) {
                top = Math.max(top, all.py[k] + 1);
                for (int y = Math.max(0, all.py[k] - 2); y <= Math.min(H - 1, all.py[k] + 2); y++) {
                    for (int x = Math.max(0, all.px[k] - 2); x <= Math.min(W - 1, all.px[k] + 2); x++) {
                        inside[y * W + x] = true;
                    }
                }
            }
            for (int i = 0; i < veg.length; i++) {
                veg[i] &= inside[i];
            }
            bandRows = vegetationThirds(veg, top);
            Vector2d travel = sim.inspect().windField().gustTravel(new Vector2d());
            speed = travel.length();
            assertTrue(speed > 0, "the meadow's gusts travel");
            double ux = travel.x / speed;
            double uz = travel.y / speed;
            // the view's horizontal direction and the wind's: 0 deg along the view, 90 across it
            double vx = Math.sin(cam.yaw());
            double vz = -Math.cos(cam.yaw());
            windAngle = Math.toDegrees(Math.acos(Math.min(1, Math.abs(ux * vx + uz * vz))));
            lattice = lattice(hf, cam, veg, bandRows[1], bandRows[3], ux, uz);
            values = new double[lattice.count][FRAMES];
            double t0 = 0;
            for (int f = 0; f < FRAMES; f++) {
                sim.step(FRAME_DT, cam);
                if (f == 0) {
                    t0 = sim.latestFrame().time();
                }
                Img img = s.render(sim.latestFrame(), cam, true, true);
                ImageMetrics.blockLuma(img, BLOCK, blocks, f);
                for (int k = 0; k < lattice.count; k++) {
                    values[k][f] = window3(img, lattice.px[k], lattice.py[k]);
                }
            }
            dt = (sim.latestFrame().time() - t0) / (FRAMES - 1);
        }
        int second = (int) Math.round(1 / dt);
        double[] middleFar = new double[2];
        for (int band = 1; band <= 2; band++) {
            middleFar[band - 1] = medianSd(blocks, veg, bx, by, bandRows[band], bandRows[band + 1], 0, FRAMES);
        }
        double[] seconds = new double[FRAMES - second + 1];
        for (int w = 0; w + second <= FRAMES; w++) {
            seconds[w] = medianSd(blocks, veg, bx, by, bandRows[1], bandRows[3], w, w + second);
        }
        double leastSecond = Arrays.stream(seconds).min().orElse(0);
        double leastLater = Arrays.stream(seconds, second, seconds.length).min().orElse(0);
        double[] sortedSeconds = seconds.clone();
        Arrays.sort(sortedSeconds);
        double medianSecond = sortedSeconds[sortedSeconds.length / 2];
        for (double[] v : values) {
            double mean = Arrays.stream(v).average().orElse(0);
            for (int f = 0; f < FRAMES; f++) {
                v[f] -= mean;
            }
        }
        double along = halfLength(lattice, values, 1, 0);
        double across = halfLength(lattice, values, 0, 1);
        int steps = (int) Math.round(TRAVEL / STEP);
        int peak = -1;
        double best = Double.NEGATIVE_INFINITY;
        double atZero = 0;
        for (int lag = 0; lag <= MAX_LAG; lag++) {
            double c = correlation(lattice, values, steps, 0, lag);
            if (lag == 0) {
                atZero = c;
            }
            if (c > best) {
                best = c;
                peak = lag;
            }
        }
        double seen = peak > 0 ? TRAVEL / (peak * dt) : Double.POSITIVE_INFINITY;
        System.out.printf(Locale.ROOT, "[look] gusts from 15 m up, %d frames at %dx%d: block luma s.d. middle %.2f, far"
                        + " %.2f (issue 41 asks >= 8); least over 1 s windows %.2f (asks >= 3; after the first second %.2f; median window %.2f); %d ground points: pattern"
                        + " half-correlation length along the wind %.2f m, across %.2f m (ratio %.2f, asks >= 2; wind %.0f deg"
                        + " from the view's direction); 2 m downwind correlates best %d frames later (%.3f; %.3f at lag"
                        + " 0): %.2f m/s against %.2f m/s (%+.0f%%, asks within 20%%)%n",
                FRAMES, W, H, middleFar[0], middleFar[1], leastSecond, leastLater, medianSecond, lattice.count, along, across, across / along,
                windAngle, peak, best, atZero, seen, speed, 100 * (seen / speed - 1));
        assertTrue(lattice.count >= 500, "ground points seen in the middle and far field: " + lattice.count);
        // issue 41's figures
        assertTrue(middleFar[0] >= 8 && middleFar[1] >= 8, "the wind shows in the middle and far field (>= 8/255): "
                + Arrays.toString(middleFar));
        assertTrue(leastSecond >= 3, "every second shows the wind (>= 3/255), the first included: " + leastSecond);
        assertTrue(across >= 2 * along, "gust patterns at least twice as long across the wind as along it: " + across
                + " vs " + along + " m");
        assertTrue(peak > 0 && best >= atZero + 0.03, "the pattern travels downwind: peak at " + peak
                + " frames, " + best + " against " + atZero + " at lag 0");
        assertTrue(Math.abs(seen / speed - 1) <= 0.2, "it travels at " + seen + " m/s, the gusts at " + speed);
    }

    /**
     * The rows (GL order, bottom up) that cut the vegetation's rows below {@code top} into thirds: {first,
     * near/middle, middle/far, one past the last}.
     */
    private static int[] vegetationThirds(boolean[] veg, int top) {
        int lo = -1;
        int hi = -1;
        for (int y = 0; y < top; y++) {
            int n = 0;
            for (int x = 0; x < W; x++) {
                n += veg[y * W + x] ? 1 : 0;
            }
            if (n >= W / 4) {
                lo = lo < 0 ? y : lo;
                hi = y + 1;
            }
        }
        assertTrue(lo >= 0 && hi - lo >= 3 * BLOCK * 2, "vegetation rows " + lo + ".." + hi);
        return new int[] {lo, lo + (hi - lo) / 3, lo + 2 * (hi - lo) / 3, hi};
    }

    /** Median over the blocks wholly in rows [y0, y1) and at least half vegetation of their s.d. over frames [f0, f1). */
    private static double medianSd(double[][] blocks, boolean[] veg, int bx, int by, int y0, int y1, int f0, int f1) {
        double[] sds = new double[bx * by];
        int n = 0;
        for (int j = 0; j < by; j++) {
            if (j * BLOCK < y0 || (j + 1) * BLOCK > y1) {
                continue;
            }
            for (int i = 0; i < bx; i++) {
                int in = 0;
                for (int y = j * BLOCK; y < (j + 1) * BLOCK; y++) {
                    for (int x = i * BLOCK; x < (i + 1) * BLOCK; x++) {
                        in += veg[y * W + x] ? 1 : 0;
                    }
                }
                if (2 * in >= BLOCK * BLOCK) {
                    sds[n++] = ImageMetrics.sd(Arrays.copyOfRange(blocks[j * bx + i], f0, f1));
                }
            }
        }
        assertTrue(n > 0, "vegetation blocks in rows " + y0 + ".." + y1);
        double[] v = Arrays.copyOf(sds, n);
        Arrays.sort(v);
        return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    }

    /** Ground points on the wind-aligned lattice: lattice coordinates, pixels, and a lookup by coordinates. */
    private record Lattice(int count, int[] iu, int[] iv, int[] px, int[] py, Map<Long, Integer> at) {
        int find(int u, int v) {
            Integer k = at.get(((long) u << 32) ^ (v & 0xffffffffL));
            return k == null ? -1 : k;
        }
    }

    /** The lattice points inside the terrain (1 m in) seen on vegetation in rows [y0, y1). */
    private static Lattice lattice(Heightfield hf, ViewCamera cam, boolean[] veg, int y0, int y1, double ux, double uz) {
        Matrix4f vp = cam.viewProjection(new Matrix4f());
        double cx = hf.minX() + hf.sizeX() / 2;
        double cz = hf.minZ() + hf.sizeZ() / 2;
        int reach = (int) Math.ceil(Math.hypot(hf.sizeX(), hf.sizeZ()) / STEP);
        int cap = (2 * reach + 1) * (2 * reach + 1);
        int[] iu = new int[cap];
        int[] iv = new int[cap];
        int[] px = new int[cap];
        int[] py = new int[cap];
        Map<Long, Integer> at = new HashMap<>();
        int n = 0;
        for (int u = -reach; u <= reach; u++) {
            for (int v = -reach; v <= reach; v++) {
                // u along the wind (ux, uz), v across it (-uz, ux)
                double x = cx + STEP * (u * ux - v * uz);
                double z = cz + STEP * (u * uz + v * ux);
                if (x < hf.minX() + 1 || x > hf.maxX() - 1 || z < hf.minZ() + 1 || z > hf.maxZ() - 1) {
                    continue;
                }
                Vector4f c = new Vector4f((float) x, (float) hf.height(x, z), (float) z, 1f).mul(vp);
                if (c.w <= 0) {
                    continue;
                }
                int sx = (int) Math.floor((c.x / c.w * 0.5 + 0.5) * W);
                int sy = (int) Math.floor((c.y / c.w * 0.5 + 0.5) * H);
                if (sx < 2 || sx >= W - 2 || sy < y0 || sy >= y1 || !veg[sy * W + sx]) {
                    continue;
                }
                iu[n] = u;
                iv[n] = v;
                px[n] = sx;
                py[n] = sy;
                at.put(((long) u << 32) ^ (v & 0xffffffffL), n);
                n++;
            }
        }
        return new Lattice(n, iu, iv, px, py, at);
    }

    /** Mean luma of the 3x3 pixels around (x, y). */
    private static double window3(Img img, int x, int y) {
        double sum = 0;
        for (int j = -1; j <= 1; j++) {
            for (int i = -1; i <= 1; i++) {
                sum += ImageMetrics.luma(img.at(x + i, Math.max(0, Math.min(H - 1, y + j))));
            }
        }
        return sum / 9;
    }

    /**
     * Pooled correlation of each point's anomaly with that of the point (du, dv) lattice steps away,
     * {@code lag} frames later, over the pairs whose pixel windows do not overlap.
     */
    private static double correlation(Lattice l, double[][] a, int du, int dv, int lag) {
        double ab = 0;
        double aa = 0;
        double bb = 0;
        for (int k = 0; k < l.count; k++) {
            int q = l.find(l.iu[k] + du, l.iv[k] + dv);
            if (q < 0 || (Math.abs(l.px[q] - l.px[k]) < 3 && Math.abs(l.py[q] - l.py[k]) < 3)) {
                continue;
            }
            double[] x = a[k];
            double[] y = a[q];
            for (int t = 0; t + lag < FRAMES; t++) {
                ab += x[t] * y[t + lag];
                aa += x[t] * x[t];
                bb += y[t + lag] * y[t + lag];
            }
        }
        return aa > 0 && bb > 0 ? ab / Math.sqrt(aa * bb) : 0;
    }

    /** Metres at which the pattern's correlation along lattice direction (du, dv) first falls to 0.5. */
    private static double halfLength(Lattice l, double[][] a, int du, int dv) {
        double previous = 1;
        for (int s = 1; s <= MAX_OFFSET; s++) {
            double c = correlation(l, a, s * du, s * dv, 0);
            if (c <= 0.5) {
                double f = (previous - 0.5) / Math.max(1e-9, previous - c);
                return STEP * (s - 1 + f);
            }
            previous = c;
        }
        return STEP * MAX_OFFSET;
    }
}
