package com.example.consumer.engines;

import com.jme3.asset.AssetManager;
import java.util.List;
import org.jecosys.gdx.PlantLayer;
import org.jecosys.gdx.PlantLayerLoader;
import org.jecosys.jme.PlantAppState;
import org.jecosys.jme.SceneAssetLoader;

/**
 * A libGDX game's and a jMonkeyEngine game's entry points into JEcoSys, compiled against the released
 * adapters (no engine is started).
 */
public final class Adapters {
    private Adapters() {
    }

    /** The adapters' main types: libGDX's layer and asset loader, jME's app state and asset loader. */
    public static List<Class<?>> types() {
        return List.of(PlantLayer.class, PlantLayerLoader.class, PlantAppState.class, SceneAssetLoader.class);
    }

    /** Registers the scene loader with a jME asset manager, as a jME game does at start. */
    public static void register(AssetManager assets) {
        assets.registerLoader(SceneAssetLoader.class, SceneAssetLoader.EXTENSION);
    }
}
