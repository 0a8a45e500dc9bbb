package org.jecosys.jme;

import com.jme3.app.Application;
import com.jme3.app.state.BaseAppState;
import com.jme3.asset.AssetLoadException;
import com.jme3.post.SceneProcessor;
import com.jme3.profile.AppProfiler;
import com.jme3.renderer.RenderManager;
import com.jme3.renderer.ViewPort;
import com.jme3.renderer.queue.RenderQueue;
import com.jme3.texture.FrameBuffer;
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
import org.jecosys.scene.Scenes;
import org.jecosys.sim.Simulation;

/**
 * JEcoSys plants in a jMonkeyEngine application: steps the {@link Simulation} in {@link #update} and
 * draws the plants in the application's main viewport with its camera.
 * <pre>{@code
 * assetManager.registerLoader(SceneAssetLoader.class, SceneAssetLoader.EXTENSION);
 * PlantAppState plants = new PlantAppState(assetManager.loadAsset(new SceneKey("Scenes/meadow.xml")));
 * stateManager.attach(plants);
 * WindSource player = plants.simulation().attachAgent(FlowDef.point("player", FlowKind.SOURCE, 0, 0, 20));
 * // each frame: plants.simulation().moveAgent(player, x, z)
 * }</pre>
 * The plants are drawn by a {@link SceneProcessor} placed first in the main viewport's processors, in
 * its {@code postFrame}: after jME's opaque, sky and transparent buckets, depth-tested against them,
 * before the translucent bucket, the filters of a {@code FilterPostProcessor} (which then apply to the
 * plants too) and the GUI. It works on the core profile ({@code AppSettings.LWJGL_OPENGL32}, the
 * default, and later) and on the compatibility profile ({@code LWJGL_OPENGL2}) where the driver offers
 * OpenGL 3.3 in it. The renderer shares jME's context and puts back every GL state it changes.
 *
 * <p>The plants are lit by the lights on the application's root node (its sun and ambient light,
 * {@link #setLightsFrom}) and fogged by the viewport's {@code FogFilter} as the rest of the picture.
 *
 * <p>Threads: jME's render thread ("jME3 Main") initializes, updates, draws and cleans up the state,
 * as jME does for every app state. The game may queue commands on the {@link #simulation()} from any
 * thread (agents, flows). The simulation steps with the camera as it is when the state updates
 * (after input, and after the app states attached before this one); nothing allocates per frame. With
 * the state disabled the plants neither move nor show. {@link #cleanup} (detaching the state, or the
 * application stopping) deletes the GL objects and closes the simulation.
 */
public class PlantAppState extends BaseAppState {
    private final Simulation simulation;
    private final RenderSettings settings;
    private final JmeCamera stepCamera = new JmeCamera();
    private final Hook hook = new Hook();
    /** The game's other viewports that draw the plants ({@link #addViewPort}); render thread. */
    private final java.util.ArrayList<Hook> others = new java.util.ArrayList<>();
    private RenderManager renderManager;
    private GlContext gl;
    private SceneRenderer renderer;
    private ViewPort viewPort;
    private volatile DrawQuality quality;
    private DrawQuality applied;
    /** The node whose lights light the plants, or null for the settings' own light; render thread. */
    private com.jme3.scene.Spatial lightsFrom;
    /** Whether the game chose {@link #lightsFrom} (otherwise the root node at initialisation). */
    private boolean lightsChosen;
    /** jME's gamma correction: its light colours are linear. */
    private boolean gamma;

    /**
     * The plants of a scene: builds its simulation now, on the calling thread (the render thread in
     * {@code simpleInitApp}, or a loading thread), with the scene's worker count and its
     * {@code <render>} look. The state owns the simulation and closes it in {@link #cleanup}; close
     * {@link #simulation()} yourself if the state is never attached. Allocates.
     *
     * @param scene a scene from {@link SceneAssetLoader} (or {@code SceneFiles.read})
     * @throws AssetLoadException when an image of the scene cannot be decoded
     */
    public PlantAppState(Scene scene) {
        this(scene, 0);
    }

    /**
     * As {@link #PlantAppState(Scene)} with a given number of animation workers.
     *
     * @param scene   the scene
     * @param workers animation worker threads, in [0, 256]; 0 keeps the scene's setting
     * @throws AssetLoadException when an image of the scene cannot be decoded
     */
    public PlantAppState(Scene scene, int workers) {
        this(build(Require.nonNull("scene", scene), Require.range("workers", workers, 0, 256)),
                RenderSettings.of(scene.def()));
    }

    /**
     * The plants of a simulation the game built itself ({@code Scenes.simulation}, on any thread); the
     * state owns it from now on and closes it in {@link #cleanup}. Any thread; allocates.
     *
     * @param simulation the plants
     * @param settings   the look ({@code RenderSettings.of(scene.def())} for the scene's own light)
     */
    public PlantAppState(Simulation simulation, RenderSettings settings) {
        this.simulation = Require.nonNull("simulation", simulation);
        this.settings = Require.nonNull("settings", settings);
    }

    /**
     * Chooses the far plants' thinning the state applies when it is attached ({@link DrawQuality});
     * null (the default): low on a software rasteriser, said once in the log, the scene's own on a GPU
     * ({@link SoftwareQuality}). Call before attaching; any thread; no allocation.
     *
     * @param quality the game's choice, or null
     */
    public void setQuality(DrawQuality quality) {
        this.quality = quality;
    }

    /** {@return the quality applied at attach time, or null when the scene's own thinning was kept (or not yet attached)} */
    public DrawQuality quality() {
        return applied;
    }

    private static Simulation build(Scene scene, int workers) {
        try {
            return Scenes.simulation(scene, workers, Progress.NONE);
        } catch (IOException e) {
            throw new AssetLoadException(scene.name() + ": " + e.getMessage(), e);
        }
    }

    /**
     * Makes the renderer's GL objects and puts the drawing processor first in the main viewport.
     * Render thread; allocates.
     *
     * @throws IllegalStateException when no OpenGL 3.3 context is current (the simulation is closed)
     */
    @Override
    protected void initialize(Application app) {
        try {
            gl = GlContext.current(DebugOutput.OFF);
            renderer = new SceneRenderer(gl, simulation.world(), settings);
            applied = SoftwareQuality.apply(gl, simulation, quality);
        } catch (RuntimeException e) {
            if (gl != null) {
                gl.close();
                gl = null;
            }
            simulation.close();
            throw e;
        }
        viewPort = app.getViewPort();
        renderManager = app.getRenderManager();
        gamma = app.getContext() != null && app.getContext().getSettings() != null
                && app.getContext().getSettings().isGammaCorrection();
        if (!lightsChosen && app instanceof com.jme3.app.SimpleApplication simple) {
            lightsFrom = simple.getRootNode();
        }
        hook.viewPort = viewPort;
        viewPort.getProcessors().add(0, hook); // before any FilterPostProcessor: the plants get the scene's depth and filters
    }

    /**
     * Removes the processor, deletes the renderer's GL objects and closes the simulation (stops its
     * workers). Render thread; jME calls it once.
     */
    @Override
    protected void cleanup(Application app) {
        try {
            if (viewPort != null) {
                viewPort.removeProcessor(hook);
            }
            for (Hook h : others) {
                h.viewPort.removeProcessor(h);
            }
            others.clear();
            if (renderer != null) {
                renderer.close();
            }
            if (gl != null) {
                gl.close();
            }
        } finally {
            simulation.close();
        }
    }

    /** Nothing: an enabled state steps in {@link #update} and draws in its processor. */
    @Override
    protected void onEnable() {
    }

    /** Nothing: a disabled state neither steps nor draws. */
    @Override
    protected void onDisable() {
    }

    /**
     * Steps the simulation by the frame's time, culled and levelled for the main viewport's camera.
     * Render thread; no allocation in the steady state.
     *
     * @param tpf seconds since the last frame (jME's time per frame), finite and &ge; 0
     */
    @Override
    public void update(float tpf) {
        if (lightsFrom != null) {
            JmeLights.apply(lightsFrom, gamma, settings.lighting());
        }
        for (int i = 0; i < others.size(); i++) {
            others.get(i).follow();
        }
        simulation.step(tpf, stepCamera.update(viewPort.getCamera()));
    }

    /**
     * Chooses the node whose lights light the plants, read at every {@link #update}: its first enabled
     * {@code DirectionalLight} is the sun (opposite its direction, its colour), its enabled
     * {@code AmbientLight}s the sky light, as jME's lit materials see them; a node without any light
     * leaves the light as it was. The plants' own haze is off: a {@code FogFilter} in the viewport fogs
     * them with the rest of the picture (they are drawn before the filters). With jME's gamma
     * correction on, the light colours (linear) are encoded to the display values the plants are lit
     * in. By default, for a {@code SimpleApplication}, its root node; null lights the plants with
     * {@link #settings()}{@code .lighting()} alone, as the game sets it. Render thread (or before
     * attaching); no allocation.
     *
     * @param node the node holding the game's lights (usually the root node), or null
     */
    public void setLightsFrom(com.jme3.scene.Spatial node) {
        lightsFrom = node;
        lightsChosen = true;
    }

    /** {@return the node whose lights light the plants, or null for the settings' own light} */
    public com.jme3.scene.Spatial lightsFrom() {
        return lightsFrom;
    }

    /**
     * Draws the plants in another viewport of the game too (split screen, a minimap, a rear-view
     * mirror), and animates what its camera sees: the viewport's camera is a view of the simulation
     * ({@link Simulation#addView}) while the viewport is enabled and attached to the render manager,
     * and stops costing animation when it is disabled or removed. Call after the state is attached
     * (from {@code simpleInitApp} on, or the state's own initialisation). Render thread; allocates.
     *
     * @param vp a viewport of the game's render manager, other than the main one
     * @throws IllegalArgumentException when vp is null, the main viewport or already added
     * @throws IllegalStateException    when the state is not initialised yet
     */
    public void addViewPort(ViewPort vp) {
        Require.nonNull("vp", vp);
        if (renderer == null) {
            throw new IllegalStateException("attach the state (and let it initialise) before adding viewports");
        }
        if (vp == viewPort || find(vp) >= 0) {
            throw new IllegalArgumentException("viewport '" + vp.getName() + "' already draws the plants");
        }
        Hook h = new Hook();
        h.viewPort = vp;
        others.add(h);
        vp.getProcessors().add(0, h);
        h.follow();
    }

    /**
     * Stops drawing the plants in a viewport added with {@link #addViewPort} and drops its view.
     * Render thread.
     *
     * @param vp the viewport
     * @return whether it was added
     */
    public boolean removeViewPort(ViewPort vp) {
        int i = find(vp);
        if (i < 0) {
            return false;
        }
        Hook h = others.remove(i);
        h.viewPort.removeProcessor(h);
        h.setViewed(false);
        return true;
    }

    /** {@return the viewports added with {@link #addViewPort} whose cameras are views of the simulation now} */
    public int viewedViewPorts() {
        int n = 0;
        for (Hook h : others) {
            n += h.viewed ? 1 : 0;
        }
        return n;
    }

    private int find(ViewPort vp) {
        for (int i = 0; i < others.size(); i++) {
            if (others.get(i).viewPort == vp) {
                return i;
            }
        }
        return -1;
    }

    /** {@return the simulation: agents, flows, wind, level of detail; commands from any thread} */
    public Simulation simulation() {
        return simulation;
    }

    /** {@return the look the renderer reads every frame; change it on the render thread} */
    public RenderSettings settings() {
        return settings;
    }

    /** {@return the renderer (statistics, resolve path); null before {@link #initialize}; render thread} */
    public SceneRenderer renderer() {
        return renderer;
    }

    /**
     * {@return how many times jME replaced the GL context under the plants ({@code app.restart()}):
     * the renderer noticed it at its next frame and made its GL objects again; -1 before
     * {@link #initialize}} Render thread; no allocation.
     */
    public int contextGeneration() {
        return gl == null ? -1 : gl.generation();
    }

    /** Draws the plants in a viewport's postFrame; holds no resources of its own. */
    private final class Hook implements SceneProcessor {
        private boolean initialized;
        ViewPort viewPort;
        private final JmeCamera drawCamera = new JmeCamera();
        /** The viewport's camera as a view of the simulation (other viewports only); stepping thread. */
        private final JmeCamera viewCamera = new JmeCamera();
        boolean viewed;

        /** Keeps the view in step with the viewport: current while it draws, dropped when it does not. */
        void follow() {
            boolean live = viewPort.isEnabled() && (renderManager.getMainViews().contains(viewPort)
                    || renderManager.getPreViews().contains(viewPort) || renderManager.getPostViews().contains(viewPort));
            if (live) {
                viewCamera.update(viewPort.getCamera());
            }
            setViewed(live);
        }

        void setViewed(boolean on) {
            if (on && !viewed) {
                simulation.addView(viewCamera);
            } else if (!on && viewed) {
                simulation.removeView(viewCamera);
            }
            viewed = on;
        }

        @Override
        public void initialize(RenderManager rm, ViewPort vp) {
            initialized = true;
        }

        @Override
        public void reshape(ViewPort vp, int w, int h) {
            // the renderer reads the bound viewport every frame
        }

        @Override
        public boolean isInitialized() {
            return initialized;
        }

        @Override
        public void preFrame(float tpf) {
            // nothing before the scene is drawn
        }

        @Override
        public void postQueue(RenderQueue rq) {
            // nothing between queueing and drawing
        }

        @Override
        public void postFrame(FrameBuffer out) {
            if (isEnabled() && renderer != null) {
                renderer.render(simulation.latestFrame(), drawCamera.update(viewPort.getCamera()));
            }
        }

        @Override
        public void cleanup() {
            initialized = false;
        }

        @Override
        public void setProfiler(AppProfiler profiler) {
            // not profiled
        }
    }
}
