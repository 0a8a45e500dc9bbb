package org.jecosys.gdx;

import com.badlogic.gdx.files.FileHandle;
import com.badlogic.gdx.utils.Disposable;
import java.io.IOException;
import org.jecosys.math.Progress;
import org.jecosys.math.Require;
import org.jecosys.render.GlContext;
import org.jecosys.render.GlContext.DebugOutput;
import org.jecosys.render.RenderSettings;
import org.jecosys.render.SceneRenderer;
import org.jecosys.render.SoftwareQuality;
import org.jecosys.sim.DrawQuality;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneLoadException;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.Simulation;

/**
 * JEcoSys plants as a layer of a libGDX frame: a {@link Simulation} (the wind and the plants' motion,
 * on worker threads) and a {@link SceneRenderer} in libGDX's own OpenGL context (LWJGL 3 backend),
 * driven by the game's {@link com.badlogic.gdx.graphics.Camera}. In {@code ApplicationListener.render()}:
 * <pre>{@code
 * plants.update(Gdx.graphics.getDeltaTime(), camera);   // steps the simulation
 * ScreenUtils.clear(0.5f, 0.7f, 0.9f, 1, true);
 * modelBatch.begin(camera); modelBatch.render(ground, environment); modelBatch.end();
 * plants.render(camera, environment);                    // depth-tested, lit by the game's lights
 * spriteBatch.begin(); font.draw(spriteBatch, "HUD", 10, 20); spriteBatch.end();
 * }</pre>
 * The plants are drawn into whatever framebuffer and viewport libGDX has bound (the back buffer, or a
 * {@code FrameBuffer} between its {@code begin()} and {@code end()}), depth-tested against what the
 * game drew, and every GL state the renderer changes is put back, so ModelBatch and SpriteBatch
 * carry on as if nothing happened. Ask for a 24-bit depth buffer and 4 samples
 * ({@code config.setBackBufferConfig(8, 8, 8, 8, 24, 0, 4)}; libGDX's default is 16 bits and none).
 * On a software rasteriser the layer thins far plants by itself ({@link SoftwareQuality}).
 *
 * <p>Threads: libGDX's render thread (the one that runs {@code create()} and {@code render()}) makes,
 * draws and disposes the layer; {@link #update} steps the simulation on that thread and its workers.
 * The game may queue commands on the {@link #simulation()} from any thread (agents, flows). Neither
 * {@link #update} nor {@link #render} allocates in the steady state. Load a layer off the render
 * thread with {@link PlantLayerLoader} and libGDX's {@code AssetManager}, or at once with
 * {@link #load(FileHandle)}.
 */
public final class PlantLayer implements Disposable {
    private final Simulation simulation;
    private final RenderSettings settings;
    private final GlContext gl;
    private final SceneRenderer renderer;
    private final GdxCamera camera = new GdxCamera();
    /** The camera {@link #update} stepped with last, drawn without a view of its own. */
    private com.badlogic.gdx.graphics.Camera stepping;
    private final RenderedViews views;
    private boolean disposed;
    /** The quality applied when the layer was made, or null for the scene's own. */
    private final DrawQuality applied;

    /**
     * Makes the renderer's GL objects for a simulation. Render thread (libGDX's GL context current);
     * allocates and uploads the plants' static data.
     *
     * @param simulation the plants; the layer owns it from now on and closes it in {@link #dispose()}
     *                   (also when this constructor fails)
     * @param settings   the look ({@link RenderSettings#of(org.jecosys.scene.SceneDef)} for the
     *                   scene's own light; {@code setTerrain(true)} adds the library's terrain mesh); read
     *                   every frame, so the game may change it between frames
     * @throws IllegalStateException when no OpenGL 3.3 context is current on this thread
     */
    public PlantLayer(Simulation simulation, RenderSettings settings) {
        this(simulation, settings, null);
    }

    /**
     * As {@link #PlantLayer(Simulation, RenderSettings)} with a draw quality: the far plants' thinning
     * ({@link SoftwareQuality#apply}). Render thread; allocates.
     *
     * @param simulation the plants, owned by the layer from now on
     * @param settings   the look, read every frame
     * @param quality    the game's choice, or null: low on a software rasteriser (said once in the
     *                   log), the scene's own on a GPU
     * @throws IllegalStateException when no OpenGL 3.3 context is current on this thread
     */
    public PlantLayer(Simulation simulation, RenderSettings settings, DrawQuality quality) {
        Require.nonNull("simulation", simulation);
        Require.nonNull("settings", settings);
        GlContext g = null;
        try {
            g = GlContext.current(DebugOutput.OFF);
            renderer = new SceneRenderer(g, simulation.world(), settings);
            applied = SoftwareQuality.apply(g, simulation, quality);
        } catch (RuntimeException e) {
            if (g != null) {
                g.close();
            }
            simulation.close();
            throw e;
        }
        this.simulation = simulation;
        this.settings = settings;
        this.gl = g;
        this.views = new RenderedViews(simulation);
    }

    /**
     * Reads a scene file, builds its simulation and makes the layer, all on the calling thread, with
     * the scene's worker count and its {@code <render>} look (no library terrain). Render thread;
     * allocates. For large scenes prefer {@link PlantLayerLoader}, which reads and builds on the asset
     * manager's thread.
     *
     * @param sceneFile the scene's XML; the images it names are its siblings ({@link GdxScenes})
     * @return the layer
     * @throws SceneLoadException when the scene is not valid or an image is missing or corrupt
     * @throws IOException        when an image cannot be decoded
     */
    public static PlantLayer load(FileHandle sceneFile) throws SceneLoadException, IOException {
        Scene scene = GdxScenes.read(sceneFile);
        return new PlantLayer(Scenes.simulation(scene, 0, Progress.NONE), RenderSettings.of(scene.def()));
    }

    /** {@return the draw quality applied when the layer was made, or null when the scene's own thinning was kept} */
    public DrawQuality quality() {
        return applied;
    }

    /**
     * Steps the simulation by the frame's time: the fixed steps that {@code deltaSeconds} completes
     * (a long pause is capped, see {@link Simulation#step}), with the force field culled and levelled
     * for {@code camera}. Call once per frame, typically first in {@code render()} with
     * {@code Gdx.graphics.getDeltaTime()}. Render thread (the stepping thread); no allocation in the
     * steady state.
     *
     * @param deltaSeconds time since the last frame, seconds, finite and &ge; 0
     * @param camera       the game's camera, after its {@code update()}
     * @throws IllegalStateException when the layer was disposed
     */
    public void update(float deltaSeconds, com.badlogic.gdx.graphics.Camera camera) {
        checkLive();
        stepping = camera;
        views.tick();
        simulation.step(deltaSeconds, this.camera.update(camera));
    }

    /**
     * Draws the newest simulated frame with {@code camera}'s matrices into the bound framebuffer and
     * viewport, depth-tested against what is in the depth buffer; puts back every GL state it changes.
     * Call between the game's 3D pass ({@code modelBatch.end()}) and its 2D pass
     * ({@code spriteBatch.begin()}); may be called more than once per frame (split screen, mirrors).
     * A camera other than the one {@link #update} steps with is registered as a view of the simulation
     * the first time it is drawn, so what it sees animates too, and dropped once it has not been drawn
     * for 30 updates (a removed viewport stops costing animation; {@link #drawnViews()}).
     * Render thread; no allocation in the steady state.
     *
     * @param camera the camera to draw with, after its {@code update()}; its aspect should match the
     *               viewport's
     * @throws IllegalStateException when the layer was disposed, or this is not the render thread
     */
    public void render(com.badlogic.gdx.graphics.Camera camera) {
        checkLive();
        renderer.render(simulation.latestFrame(), camera == stepping ? this.camera.update(camera) : views.drawn(camera));
    }

    /**
     * As {@link #render(com.badlogic.gdx.graphics.Camera)}, lit and fogged by the game's libGDX
     * {@link com.badlogic.gdx.graphics.g3d.Environment} (the one given to {@code ModelBatch.render}), as
     * libGDX's default shader lights the game's models: its first directional light is the sun, its
     * {@code ColorAttribute.AmbientLight} the sky light, its {@code ColorAttribute.Fog} the haze, full
     * at {@code camera.far / 1.09} and growing as the distance squared; what the environment lacks, the
     * plants lack too (no directional light, no sun; no fog attribute, no haze). The values are written
     * into {@link #settings()}{@code .lighting()} before drawing, so a later {@code render(camera)}
     * keeps them. Render thread; no allocation in the steady state.
     *
     * @param camera      the camera to draw with, after its {@code update()}
     * @param environment the game's lights and fog, not null
     * @throws IllegalStateException when the layer was disposed, or this is not the render thread
     */
    public void render(com.badlogic.gdx.graphics.Camera camera, com.badlogic.gdx.graphics.g3d.Environment environment) {
        checkLive();
        Require.nonNull("environment", environment);
        GdxLights.apply(environment, camera, settings.lighting());
        render(camera);
    }

    /** {@return the game cameras other than the stepping one that are registered as views now} */
    public int drawnViews() {
        return views.count();
    }

    /** {@return the simulation: agents, flows, wind, level of detail; commands from any thread} */
    public Simulation simulation() {
        return simulation;
    }

    /** {@return the renderer (statistics, the plant renderer's resolve path); render thread} */
    public SceneRenderer renderer() {
        return renderer;
    }

    /** {@return the look the renderer reads every frame; change it on the render thread} */
    public RenderSettings settings() {
        return settings;
    }

    /**
     * Deletes the renderer's GL objects and closes the simulation (stops its workers). libGDX's
     * {@code AssetManager} calls it when the asset is unloaded. Render thread; idempotent.
     */
    @Override
    public void dispose() {
        if (disposed) {
            return;
        }
        disposed = true;
        try {
            renderer.close();
            gl.close();
        } finally {
            simulation.close();
        }
    }

    private void checkLive() {
        if (disposed) {
            throw new IllegalStateException("the plant layer is disposed");
        }
    }
}
