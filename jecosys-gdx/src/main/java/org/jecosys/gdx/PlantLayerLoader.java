package org.jecosys.gdx;

import com.badlogic.gdx.assets.AssetDescriptor;
import com.badlogic.gdx.assets.AssetLoaderParameters;
import com.badlogic.gdx.assets.AssetManager;
import com.badlogic.gdx.assets.loaders.AsynchronousAssetLoader;
import com.badlogic.gdx.assets.loaders.FileHandleResolver;
import com.badlogic.gdx.files.FileHandle;
import com.badlogic.gdx.utils.Array;
import com.badlogic.gdx.utils.GdxRuntimeException;
import java.io.IOException;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentMap;
import org.jecosys.math.Progress;
import org.jecosys.render.RenderSettings;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneLoadException;
import org.jecosys.scene.Scenes;
import org.jecosys.sim.Simulation;

/**
 * Loads scene files as {@link PlantLayer}s through libGDX's {@link AssetManager}:
 * <pre>{@code
 * assets.setLoader(PlantLayer.class, new PlantLayerLoader(assets.getFileHandleResolver()));
 * assets.load("meadow/patch.xml", PlantLayer.class);
 * ...
 * if (assets.update()) plants = assets.get("meadow/patch.xml", PlantLayer.class);
 * }</pre>
 * The heavy work runs in {@link #loadAsync} on the asset manager's loader thread: reading and checking
 * the scene and its images ({@link GdxScenes}: images are the scene file's siblings, of the same
 * {@code FileType}), then building the simulation (terrain, distribution, pose tables, worker threads).
 * {@link #loadSync} runs on the render thread and only makes the renderer's GL objects. Unloading the
 * asset disposes the layer ({@link PlantLayer#dispose()}); unloading it while it loads closes the
 * simulation built so far.
 *
 * <p>A scene that fails is reported through the asset manager (its {@code AssetErrorListener}, or a
 * {@link GdxRuntimeException} from {@code update()}/{@code finishLoading()}) with the scene's problems as
 * {@code PATH:LINE:COL: message}. One loader may load several scenes at once (each asset name once at
 * a time); it allocates (load time).
 */
public final class PlantLayerLoader extends AsynchronousAssetLoader<PlantLayer, PlantLayerLoader.Parameters> {
    /**
     * How a scene is loaded; libGDX-style public fields, read when the load starts.
     */
    public static final class Parameters extends AssetLoaderParameters<PlantLayer> {
        /** Animation worker threads, in [0, 256]; 0 (the default) keeps the scene's setting. */
        public int workers;
        /** Whether the library draws the scene's terrain mesh under the plants (default: the game draws its ground). */
        public boolean terrain;
        /**
         * The far plants' thinning ({@link org.jecosys.sim.DrawQuality}); null (the default): low on a
         * software rasteriser, said once in the log, and the scene's own on a GPU.
         */
        public org.jecosys.sim.DrawQuality quality;

        /** The defaults: the scene's worker count, no library terrain. */
        public Parameters() {
        }
    }

    /** What loadAsync built for a file, until loadSync takes it or the load is cancelled. */
    private static final class Pending {
        Scene scene;
        Simulation simulation;
        boolean cancelled;
    }

    private final ConcurrentMap<String, Pending> pending = new ConcurrentHashMap<>();

    /**
     * A loader that resolves scene names with {@code resolver} (pass the asset manager's own,
     * {@code assets.getFileHandleResolver()}).
     *
     * @param resolver turns asset names into file handles (internal, classpath, local, ...)
     */
    public PlantLayerLoader(FileHandleResolver resolver) {
        super(resolver);
    }

    /** No dependencies: the scene's images are read by {@link #loadAsync} itself. */
    @Override
    @SuppressWarnings("rawtypes")
    public Array<AssetDescriptor> getDependencies(String fileName, FileHandle file, Parameters parameter) {
        return null;
    }

    /**
     * Reads and checks the scene and its images and builds its simulation. The asset manager's loader
     * thread; no GL; allocates.
     */
    @Override
    public void loadAsync(AssetManager manager, String fileName, FileHandle file, Parameters parameter) {
        Pending p = new Pending();
        pending.put(fileName, p);
        Scene scene;
        Simulation sim;
        try {
            scene = GdxScenes.read(file);
            sim = Scenes.simulation(scene, parameter == null ? 0 : parameter.workers, Progress.NONE);
        } catch (SceneLoadException e) {
            pending.remove(fileName, p);
            throw new GdxRuntimeException(e.getMessage(), e);
        } catch (IOException e) {
            pending.remove(fileName, p);
            throw new GdxRuntimeException(fileName + ": " + e.getMessage(), e);
        } catch (RuntimeException e) {
            pending.remove(fileName, p);
            throw e;
        }
        synchronized (p) {
            if (p.cancelled) {
                sim.close();
                return;
            }
            p.scene = scene;
            p.simulation = sim;
        }
    }

    /**
     * Makes the layer's GL objects for the simulation {@link #loadAsync} built. Render thread;
     * allocates.
     */
    @Override
    public PlantLayer loadSync(AssetManager manager, String fileName, FileHandle file, Parameters parameter) {
        Pending p = pending.remove(fileName);
        if (p == null || p.simulation == null) {
            throw new GdxRuntimeException(fileName + ": the scene was not built (loadAsync did not finish)");
        }
        RenderSettings settings = RenderSettings.of(p.scene.def());
        settings.setTerrain(parameter != null && parameter.terrain);
        return new PlantLayer(p.simulation, settings, parameter == null ? null : parameter.quality); // closes the simulation if it fails
    }

    /** {@return the simulation loadAsync built for an asset and loadSync has not taken, or null} Tests. */
    Simulation pending(String fileName) {
        Pending p = pending.get(fileName);
        return p == null ? null : p.simulation;
    }

    /** Closes the simulation of a load cancelled before {@link #loadSync}. Any thread. */
    @Override
    public void unloadAsync(AssetManager manager, String fileName, FileHandle file, Parameters parameter) {
        Pending p = pending.remove(fileName);
        if (p == null) {
            return;
        }
        synchronized (p) {
            p.cancelled = true;
            if (p.simulation != null) {
                p.simulation.close();
                p.simulation = null;
            }
        }
    }
}
