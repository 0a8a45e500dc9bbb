package org.jecosys.jme;

import com.jme3.asset.AssetKey;
import com.jme3.asset.cache.AssetCache;
import org.jecosys.scene.Scene;

/**
 * The asset key of a JEcoSys scene file, so that {@code assetManager.loadAsset(new SceneKey(name))}
 * returns a {@link Scene}, with {@link SceneAssetLoader} registered for
 * {@link SceneAssetLoader#EXTENSION}: the key reports that extension whatever its file is called, so
 * a scene named {@code meadow.xml} reaches the scene loader while the game's other {@code .xml}
 * assets keep theirs. The
 * scene is not cached: it holds the bytes of its images, and a game builds its simulation from it
 * once; load it again to build another. Any thread; allocates.
 */
public class SceneKey extends AssetKey<Scene> {
    /**
     * A key for the scene file at an asset path.
     *
     * @param name the asset path, e.g. {@code "Scenes/meadow.xml"} (found by the asset manager's
     *             locators: the classpath, and folders registered with {@code FileLocator})
     */
    public SceneKey(String name) {
        super(name);
        extension = SceneAssetLoader.EXTENSION;
    }

    /** For jME's serialisation only. */
    public SceneKey() {
        extension = SceneAssetLoader.EXTENSION;
    }

    /** {@return {@link SceneAssetLoader#EXTENSION}, whatever the file's name (see the class comment)} */
    @Override
    public String getExtension() {
        return SceneAssetLoader.EXTENSION;
    }

    /** {@return null: a scene is not cached (see the class comment)} */
    @Override
    public Class<? extends AssetCache> getCacheType() {
        return null;
    }
}
