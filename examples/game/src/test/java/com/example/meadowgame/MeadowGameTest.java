package com.example.meadowgame;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.render.Screenshot;
import org.jecosys.sim.Frame;
import org.jecosys.sim.World;
import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;

/**
 * The example game, headless (GLFW's null platform with an EGL context, Mesa's llvmpipe here): its
 * own sky, ground and HUD are where it drew them with the library's plants in between, the player
 * pushes the grass and leaves a trail through the meadow's grasses, the game's own flow bends plants,
 * and the game's classpath holds only the published modules.
 */
class MeadowGameTest {
    private static final int W = 320;
    private static final int H = 200;
    private static final int FRAMES = 24;
    private static final Path SCENE = Path.of("scenes/c1.xml");

    private record Run(double bendNearPlayer, double bendNearBreeze, int sky, int hud, int ground, int plants) {
    }

    /** Plays FRAMES frames at 30 fps and measures the last one. */
    private static Run play(double playerStrength, boolean breeze) throws Exception {
        ByteBuffer px = MemoryUtil.memAlloc(4 * W * H);
        try (MeadowGame game = new MeadowGame(new MeadowGame.Options(SCENE, W, H, true, playerStrength, breeze))) {
            Frame frame = null;
            for (int i = 0; i < FRAMES; i++) {
                frame = game.frame(1 / 30.0);
            }
            game.read(px);
            if (playerStrength > 0 && breeze) {
                Files.createDirectories(Path.of("target/example-game"));
                Screenshot.writePng(Path.of("target/example-game/frame.png"), px, W, H);
            }
            World world = game.simulation().world();
            double nearPlayer = meanBend(world, frame, game.playerX(), game.playerZ(), 0, 1.5);
            double nearBreeze = meanBend(world, frame, game.breeze().centreX(), game.breeze().centreZ(), 2.5, 5);
            int sky = 0;
            int hud = 0;
            int ground = 0;
            int plants = 0;
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    int r = px.get(4 * (y * W + x)) & 255;
                    int g = px.get(4 * (y * W + x) + 1) & 255;
                    int b = px.get(4 * (y * W + x) + 2) & 255;
                    if (r == 240 && g == 200 && b == 24) {
                        hud++;
                    } else if (b > r + 20 && b > g && y > H / 2) {
                        sky++;
                    } else if (r > g && g > b && r - b > 25) {
                        ground++;
                    } else if (g >= r && g > b + 8) {
                        // green (the thin blades are blended by their coverage over the brown ground)
                        plants++;
                    }
                }
            }
            return new Run(nearPlayer, nearBreeze, sky, hud, ground, plants);
        } finally {
            MemoryUtil.memFree((java.nio.Buffer) px);
        }
    }

    /** Mean |pose coordinate| of the visible components of plants in the ring [r0, r1) around (x, z). */
    private static double meanBend(World world, Frame frame, double x, double z, double r0, double r1) {
        double sum = 0;
        int n = 0;
        for (int p = 0; p < world.plantCount(); p++) {
            double d = Math.hypot(world.plantX(p) - x, world.plantZ(p) - z);
            if (d < r0 || d >= r1) {
                continue;
            }
            for (int c = world.firstComponent(p), e = c + world.componentsOf(p); c < e; c++) {
                sum += Math.abs(frame.poseCoord(c));
                n++;
            }
        }
        assertTrue(n > 0, "plants near (" + x + ", " + z + ")");
        return sum / n;
    }

    @Test
    void theGameDrawsItsOwnSkyGroundAndHudAroundTheLibrarysPlants() throws Exception {
        Run run = play(MeadowGame.PLAYER_STRENGTH, true);
        assertTrue(run.sky() > W * H / 8, "the game's sky gradient fills the top: " + run.sky());
        assertTrue(run.ground() > W * H / 8, "the game's own ground: " + run.ground());
        assertTrue(run.plants() > 150, "the library's plants drawn over the game's ground: " + run.plants());
        // the HUD bar is drawn last, in exactly its colour, over whatever is behind it
        assertTrue(run.hud() > 300, "the game's HUD: " + run.hud());
    }

    @Test
    void thePlayerPushesTheGrassAndTheGamesOwnFlowBendsPlants() throws Exception {
        Run both = play(MeadowGame.PLAYER_STRENGTH, true);
        Run noPlayer = play(0, true);
        Run neither = play(0, false);
        assertTrue(both.bendNearPlayer() > 1.5 * noPlayer.bendNearPlayer() + 0.05,
                "plants within 1.5 m of the player bend more with the player's flow: " + both.bendNearPlayer()
                        + " vs " + noPlayer.bendNearPlayer());
        assertTrue(noPlayer.bendNearBreeze() > neither.bendNearBreeze() + 0.05,
                "the game's breeze bends the plants around its centre: " + noPlayer.bendNearBreeze() + " vs "
                        + neither.bendNearBreeze());
    }

    @Test
    void onTheMeadowThePlayerLeavesATrailOfFlattenedGrass() throws Exception {
        // the default scene's grasses recover over 10 s (<species recovery>): the circle the player
        // walks stays flattened behind it, the grass away from it stands
        java.util.List<double[]> walked = new java.util.ArrayList<>();
        try (MeadowGame game = new MeadowGame(new MeadowGame.Options(Path.of("scenes/meadow.xml"), 160, 100, true,
                MeadowGame.PLAYER_STRENGTH, true))) {
            for (int i = 0; i < 60; i++) {
                game.frame(1 / 30.0);
                if (i >= 10 && i < 40) {
                    walked.add(new double[] {game.playerX(), game.playerZ()});
                }
            }
            World world = game.simulation().world();
            int near = 0;
            int nearFlat = 0;
            int far = 0;
            int farFlat = 0;
            for (int p = 0; p < world.plantCount(); p++) {
                String species = world.plants().species().get(world.plantSpecies(p)).def().id();
                if (!species.startsWith("grass")) {
                    continue;
                }
                double d = Double.POSITIVE_INFINITY;
                for (double[] w : walked) {
                    d = Math.min(d, Math.hypot(world.plantX(p) - w[0], world.plantZ(p) - w[1]));
                }
                boolean flat = game.simulation().inspect().state().flattening(p) > 0.3f;
                if (d <= 0.3) {
                    near++;
                    nearFlat += flat ? 1 : 0;
                } else if (d > 3 && d < 10) {
                    far++;
                    farFlat += flat ? 1 : 0;
                }
            }
            System.out.println("[game] grass within 0.3 m of where the player walked 0.7-1.7 s ago: " + nearFlat
                    + " of " + near + " flattened; 3-10 m away: " + farFlat + " of " + far);
            assertTrue(near >= 5, "grass along the player's walk: " + near);
            assertTrue(nearFlat >= 0.8 * near, "flattened along the walk: " + nearFlat + " of " + near);
            assertTrue(far > 100, "grass away from the walk: " + far);
            assertEquals(0, farFlat, "flattened away from the walk");
        }
    }

    @Test
    void theGameSeesOnlyThePublishedModulesNotTheApplicationsLibraries() {
        for (String appOnly : new String[] {"picocli.CommandLine", "imgui.ImGui", "org.knowm.xchart.XYChart",
                "org.jecosys.app.Main", "org.jecosys.bench.BenchSuite"}) {
            assertThrows(ClassNotFoundException.class, () -> Class.forName(appOnly), appOnly);
        }
        assertEquals("org.jecosys.render.SceneRenderer",
                org.jecosys.render.SceneRenderer.class.getName(), "the render module is there");
    }
}
