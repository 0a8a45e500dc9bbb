package org.jecosys.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import javax.imageio.ImageIO;
import org.jecosys.math.Progress;
import org.jecosys.math.ViewCamera;
import org.jecosys.plant.ComponentMesh;
import org.jecosys.plant.GltfWriter;
import org.jecosys.plant.MeshGeometry;
import org.jecosys.plant.LodMesh;
import org.jecosys.plant.PoseTable;
import org.jecosys.plant.SpeciesModel;
import org.jecosys.render.ImageMetrics.Img;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneFiles;
import org.jecosys.sim.Frame;
import org.jecosys.sim.Simulation;
import org.jecosys.sim.World;
import org.jecosys.sim.internal.FrameWriter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 40, "Done when", for glTF meshes, drawn at 960x540 with the library's 4 samples:
 * <ul>
 * <li>a textured card modelled in glTF and bound along a leaf's skeleton covers the pixels the leaf's
 * own textured strip covers (intersection over union at least 0.9), upright and bent, with the
 * texture's bands in order from base to tip;</li>
 * <li>a rigid glTF flower head on a stalk follows the stalk's tip and turns with it over 150 frames of
 * a simulated gusty wind: on the CPU (the shader's placement, {@link ComponentMesh#place}) its origin
 * stays on the tip (within 1 cm) and its +Y along the tip's last segment; drawn, the head's pixels
 * lie around the projected tip.</li>
 * </ul>
 */
class MeshComponentsTest {
    private static final int W = 960;
    private static final int H = 540;
    private static final int[] BANDS = {0xff2828, 0xffff28, 0x28ff28, 0x2828ff};

    @TempDir
    Path dir;

    private static final String CARD_SPECIES = """
              <species id="card" name="card" maxBend="80">
                <lod maxDistance="30"/>
                <lod primitive="lines"/>
                <variation variants="1" length="0" width="0" curvature="0" tilt="0" hue="0" value="0" dryTips="0"/>
                <component id="leaf" type="leaf" segments="12" length="1" baseWidth="0.25" tipWidth="0.25"
                    mass="0.001" stiffness="5" colour="#ffffff" texture="stripes.png" lodSegments="12 4" %s/>
              </species>
            """;

    private World cardWorld(String name, String extra) throws Exception {
        Files.writeString(dir.resolve(name), "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                + "<scene version=\"1\" name=\"card\" seed=\"3\">\n  <terrain sizeX=\"4\" sizeZ=\"4\" resolution=\"17\"/>\n"
                + String.format(Locale.ROOT, CARD_SPECIES, extra)
                + "  <plant species=\"card\" x=\"0\" z=\"0\"/>\n</scene>\n");
        Scene scene = SceneFiles.read(dir.resolve(name));
        return World.build(scene.def().simulationDef(), scene.images(), 1, Progress.NONE);
    }

    @Test
    void aBoundGltfCardCoversWhatTheLeafsStripCoversUprightAndBent() throws Exception {
        BufferedImage img = new BufferedImage(32, 64, BufferedImage.TYPE_INT_ARGB);
        for (int y = 0; y < 64; y++) {
            for (int x = 0; x < 32; x++) {
                img.setRGB(x, y, 0xff000000 | BANDS[3 - y / 16]);
            }
        }
        ImageIO.write(img, "png", dir.resolve("stripes.png").toFile());
        // the card: 13 rows of 2 vertices, 1 unit wide and 4 high (bound: its height becomes the leaf's 1 m,
        // its width 0.25 m, the strip's); glTF's v runs down the image, so the base (v = 1) is the bottom row
        float[] pos = new float[3 * 26];
        float[] uv = new float[2 * 26];
        int[] idx = new int[6 * 12];
        for (int i = 0; i <= 12; i++) {
            for (int side = 0; side < 2; side++) {
                int v = 2 * i + side;
                pos[3 * v] = side == 0 ? -0.5f : 0.5f;
                pos[3 * v + 1] = 4f * i / 12;
                uv[2 * v] = side;
                uv[2 * v + 1] = 1f - i / 12f;
            }
        }
        for (int i = 0; i < 12; i++) {
            System.arraycopy(new int[] {2 * i, 2 * i + 1, 2 * i + 3, 2 * i, 2 * i + 3, 2 * i + 2}, 0, idx, 6 * i, 6);
        }
        Files.write(dir.resolve("card.glb"), GltfWriter.glb(new MeshGeometry(pos, null, uv, idx)));
        World strip = cardWorld("strip.xml", "");
        World mesh = cardWorld("mesh.xml", "mesh=\"card.glb\"");
        assertTrue(mesh.plants().species().get(0).mesh(0).vertexFromFile(0), "the near level is the file's card");
        // oblique, so that the leaf (facing +X, bending toward +X) shows its face and its bend
        ViewCamera cam = Shots.lookAt(1.5, 0.7, 1.5, 0, 0.5, 0, Math.toRadians(50), W / (double) H, 0.05, 100);
        for (float bend : new float[] {0f, 0.75f}) {
            boolean[] a = plantMask(strip, cam, bend);
            boolean[] b = plantMask(mesh, cam, bend);
            long inter = 0;
            long union = 0;
            long na = 0;
            for (int i = 0; i < a.length; i++) {
                inter += a[i] && b[i] ? 1 : 0;
                union += a[i] || b[i] ? 1 : 0;
                na += a[i] ? 1 : 0;
            }
            double iou = inter / (double) Math.max(1, union);
            System.out.printf(Locale.ROOT, "[look] glTF card vs the leaf's strip, bend %.2f: strip %d px, IoU %.3f%n",
                    bend, na, iou);
            assertTrue(na > 10_000, "the leaf is drawn large: " + na);
            assertTrue(iou >= 0.9, "the bound card covers the strip's pixels, bend " + bend + ": IoU " + iou);
        }
        // face on (the leaf faces +X) for the texture's bands
        bandsInOrder(mesh, Shots.lookAt(2.2, 0.55, 0, 0, 0.5, 0, Math.toRadians(50), W / (double) H, 0.05, 100));
    }

    /** Plant pixels (with plants against without) of the one plant bent to a share of its poses, toward +X. */
    private static boolean[] plantMask(World world, ViewCamera cam, float share) {
        try (Shots s = new Shots(world, RenderSettings.standalone(), W, H)) {
            Frame f = TestFrames.rest(world);
            int poses = world.plants().species().get(0).slotPoseTable(0, 0).poses();
            FrameWriter.set(f, world.firstComponent(0), share * (poses - 1), 0f);
            Frame decided = TestFrames.decide(world, f, cam);
            Img with = s.render(decided, cam, true, true);
            Img without = s.render(decided, cam, false, true);
            boolean[] m = new boolean[W * H];
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    m[y * W + x] = ImageMetrics.differ(with.at(x, y), without.at(x, y));
                }
            }
            return m;
        }
    }

    /** The card's bands by hue: each at least 5% of its pixels, their mean distance from the base rising. */
    private static void bandsInOrder(World world, ViewCamera cam) {
        try (Shots s = new Shots(world, RenderSettings.standalone(), W, H)) {
            Frame f = TestFrames.rest(world, cam);
            Img with = s.render(f, cam, true, true);
            Img without = s.render(f, cam, false, true);
            double[] base = Shots.project(cam, world.plantX(0), world.plantY(0), world.plantZ(0), W, H);
            long[] count = new long[4];
            double[] dist = new double[4];
            long plant = 0;
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    int p = with.at(x, y);
                    if (!ImageMetrics.differ(p, without.at(x, y))) {
                        continue;
                    }
                    plant++;
                    // the ground darkened by the card's shadow and contact is dull; the bands are vivid
                    int best = ImageMetrics.nearestHue(p, BANDS, 0.5f, 0.35f);
                    if (best < 0) {
                        continue;
                    }
                    count[best]++;
                    dist[best] += Math.hypot(x - base[0], y - base[1]);
                }
            }
            StringBuilder r = new StringBuilder();
            for (int b = 0; b < 4; b++) {
                dist[b] /= Math.max(1, count[b]);
                r.append(String.format(Locale.ROOT, " band %d: %d px at %.0f px;", b, count[b], dist[b]));
            }
            System.out.println("[look] glTF card's texture:" + r);
            for (int b = 0; b < 4; b++) {
                assertTrue(count[b] >= 0.05 * plant, "band " + b + " shows:" + r);
                assertTrue(b == 0 || dist[b] > dist[b - 1] + 20, "band " + b + " beyond band " + (b - 1) + ":" + r);
            }
        }
    }

    @Test
    void aRigidGltfHeadFollowsItsStalksTipAndTurnsWithItInWind() throws Exception {
        // a disc of 8 triangles 1 unit across, its centre raised 0.1 along +Y (0.008 m: the head's +Y)
        int n = 8;
        float[] pos = new float[3 * (n + 1)];
        int[] idx = new int[3 * n];
        pos[1] = 0.1f;
        for (int j = 0; j < n; j++) {
            double a = 2 * Math.PI * j / n;
            pos[3 * (j + 1)] = (float) (0.5 * Math.cos(a));
            pos[3 * (j + 1) + 2] = (float) (0.5 * Math.sin(a));
            idx[3 * j] = 0;
            idx[3 * j + 1] = 1 + j;
            idx[3 * j + 2] = 1 + (j + 1) % n;
        }
        Files.write(dir.resolve("head.glb"), GltfWriter.glb(new MeshGeometry(pos, null, null, idx)));
        Files.writeString(dir.resolve("flower.xml"), """
                <?xml version="1.0" encoding="UTF-8"?>
                <scene version="1" name="glTF head" seed="5">
                  <terrain sizeX="4" sizeZ="4" resolution="17"/>
                  <species id="flower" maxBend="80">
                    <lod maxDistance="30"/>
                    <lod primitive="lines"/>
                    <variation variants="1" length="0" width="0" curvature="0" tilt="0" hue="0" value="0" dryTips="0"/>
                    <component id="stalk" type="stalk" segments="8" length="0.6" baseWidth="0.01" tipWidth="0.006"
                        mass="0.003" stiffness="0.05" colour="#30a030" lodSegments="8 3"/>
                    <component id="head" type="head" attachTo="stalk" segments="2" length="0.03" baseWidth="0.02"
                        tipWidth="0.02" mass="0.002" stiffness="0.2" colour="#ff20ff" mesh="head.glb" meshMode="rigid"
                        meshScale="0.08" lodSegments="2 1"/>
                  </species>
                  <plant species="flower" x="0" z="0"/>
                  <wind>
                    <gust id="wind" strength="6" direction="20" noiseScale="2" noiseFrequency="0.5" seed="3"/>
                  </wind>
                  <camera x="0" y="0.4" z="1.6"/>
                </scene>
                """);
        Scene scene = SceneFiles.read(dir.resolve("flower.xml"));
        World world = World.build(scene.def().simulationDef(), scene.images(), 1, Progress.NONE);
        SpeciesModel m = world.plants().species().get(0);
        LodMesh near = m.mesh(0);
        int headVertex = -1;
        for (int v = 0; v < near.vertexCount(); v++) {
            if (near.vertexFromFile(v)) {
                assertEquals(0, near.vertexSlot(v), "placed by the stalk's slot");
                assertEquals(1, near.vertexLookSlot(v), "looking like the head");
                headVertex = headVertex < 0 ? v : headVertex;
            }
        }
        ComponentMesh head = m.component(1).mesh(0);
        assertTrue(head.ridesParent());
        PoseTable stalk = m.slotPoseTable(0, world.plantVariant(0));
        ViewCamera cam = Shots.lookAt(0, 1.3, 1.3, 0, 0.4, 0, Math.toRadians(45), W / (double) H, 0.05, 100);
        double worstGap = 0;
        double worstTurn = 0;
        double tiltMin = 1e9;
        double tiltMax = -1e9;
        float[] o = new float[3];
        float[] o1 = new float[3];
        float[] up = new float[3];
        float[] up1 = new float[3];
        try (Simulation sim = Simulation.of(world, scene.def().simulationDef(), 1);
             Shots s = new Shots(world, RenderSettings.standalone(), W, H)) {
            for (int frame = 0; frame < 150; frame++) {
                sim.stepFixed(cam);
                Frame f = sim.latestFrame();
                int c = world.firstComponent(0);
                float q = f.poseCoord(c);
                int k = Math.min((int) q, stalk.poses() - 2);
                float w = q - k;
                // vertex 0, the disc's raised centre, is (0, 0.1, 0) x 0.08: the tip plus 0.008 m along +Y
                head.place(stalk, k, 0, up);
                head.place(stalk, k + 1, 0, up1);
                int tipK = stalk.offset(k, stalk.points() - 1);
                int tipK1 = stalk.offset(k + 1, stalk.points() - 1);
                int befK = stalk.offset(k, stalk.points() - 2);
                int befK1 = stalk.offset(k + 1, stalk.points() - 2);
                double[] tip = new double[3];
                double[] dir = new double[3];
                double dl = 0;
                for (int i = 0; i < 3; i++) {
                    tip[i] = stalk.get(tipK + i) * (1 - w) + stalk.get(tipK1 + i) * w;
                    dir[i] = tip[i] - (stalk.get(befK + i) * (1 - w) + stalk.get(befK1 + i) * w);
                    dl += dir[i] * dir[i];
                    o[i] = up[i] * (1 - w) + up1[i] * w; // the raised centre, blended as the shader blends
                }
                dl = Math.sqrt(dl);
                double along = 0;
                double off = 0;
                for (int i = 0; i < 3; i++) {
                    along += (o[i] - tip[i]) * dir[i] / dl;
                }
                for (int i = 0; i < 3; i++) {
                    off += Math.pow(o[i] - tip[i] - along * dir[i] / dl, 2);
                }
                // the centre lies 0.008 m along the tip's last segment: the origin on the tip, +Y along it
                worstGap = Math.max(worstGap, Math.abs(along - 0.008) + Math.sqrt(off));
                worstTurn = Math.max(worstTurn, Math.toDegrees(Math.atan2(Math.sqrt(off), along)));
                double tilt = Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, dir[1] / dl))));
                tiltMin = Math.min(tiltMin, tilt);
                tiltMax = Math.max(tiltMax, tilt);
                if (frame % 50 == 49) {
                    headOnScreen(s, f, cam, world, stalk, k, w);
                }
            }
        }
        System.out.printf(Locale.ROOT, "[mesh] rigid head over 150 frames: centre off its place %.5f m, its axis %.3f deg "
                + "off the tip's segment; the tip's segment leaned %.1f to %.1f deg%n", worstGap, worstTurn, tiltMin, tiltMax);
        assertTrue(tiltMax - tiltMin > 10, "the wind turns the stalk's tip: " + tiltMin + " to " + tiltMax);
        assertTrue(worstGap < 0.01, "the head's centre follows the tip within 1 cm: " + worstGap);
        assertTrue(worstTurn < 2, "the head turns with the tip: " + worstTurn + " degrees off");
    }

    /** Drawn: the head's magenta pixels lie around the projected head centre (within 12 pixels). */
    private static void headOnScreen(Shots s, Frame f, ViewCamera cam, World world, PoseTable stalk, int k, float w) {
        Frame decided = TestFrames.decide(world, f, cam);
        Img img = s.render(decided, cam, true, true);
        double sx = 0;
        double sy = 0;
        long n = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int p = img.at(x, y);
                int r = (p >> 16) & 255;
                int g = (p >> 8) & 255;
                int b = p & 255;
                if (r > g + 60 && b > g + 60) {
                    sx += x;
                    sy += y;
                    n++;
                }
            }
        }
        int c = world.firstComponent(0);
        float[] centre = new float[3];
        float[] c1 = new float[3];
        ComponentMesh head = world.plants().species().get(0).component(1).mesh(0);
        head.place(stalk, k, 0, centre);
        head.place(stalk, k + 1, 0, c1);
        double lx = centre[0] * (1 - w) + c1[0] * w;
        double ly = centre[1] * (1 - w) + c1[1] * w;
        double lz = centre[2] * (1 - w) + c1[2] * w;
        double az = f.bendAzimuth(c);
        double wx = world.plantX(0) + lx * Math.cos(az) - lz * Math.sin(az);
        double wz = world.plantZ(0) + lx * Math.sin(az) + lz * Math.cos(az);
        double[] at = Shots.project(cam, wx, world.plantY(0) + ly, wz, W, H);
        assertTrue(n > 50, "the head is drawn: " + n + " pixels");
        double gap = Math.hypot(sx / n - at[0], sy / n - at[1]);
        System.out.printf(Locale.ROOT, "[look] rigid head: %d px, centroid %.1f px from the projected centre%n", n, gap);
        assertTrue(gap < 12, "the drawn head sits where the CPU places it: " + gap + " px");
    }
}
