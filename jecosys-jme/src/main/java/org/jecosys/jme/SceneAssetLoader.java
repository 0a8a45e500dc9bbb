package org.jecosys.jme;

import com.jme3.asset.AssetInfo;
import com.jme3.asset.AssetKey;
import com.jme3.asset.AssetLoadException;
import com.jme3.asset.AssetLoader;
import com.jme3.asset.AssetManager;
import java.io.IOException;
import java.io.InputStream;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneFiles;
import org.jecosys.scene.SceneLoadException;
import org.jecosys.terrain.ImageSource;

/**
 * Loads JEcoSys scene files through jME's {@link AssetManager}, as {@link Scene}s:
 * <pre>{@code
 * assetManager.registerLoader(SceneAssetLoader.class, SceneAssetLoader.EXTENSION);
 * Scene scene = assetManager.loadAsset(new SceneKey("Scenes/meadow.xml"));
 * }</pre>
 * The loader is registered for {@value #EXTENSION}, not for {@code xml}: a {@link SceneKey} reaches it
 * whatever its file is called, and so does a plain {@code AssetKey} for a file named
 * {@code NAME.jecosys.xml}; every other {@code .xml} asset of the game (its materials, its UI) keeps its
 * own loader.
 * The images the scene names (heightmaps, resource maps) are found the same way as the scene, relative
 * to its folder: {@code "Scenes/"} plus the path the scene writes, through
 * {@code assetManager.locateAsset}, so a scene on the classpath or in a {@code FileLocator} folder
 * takes its images from there. Image paths are confined to the scene's folder, as
 * {@link ImageSource#folder} does for files on disk: an absolute path, or {@code ..} that leads out of
 * it, is refused.
 *
 * <p>A scene that fails throws {@link AssetLoadException} whose message lists its problems as
 * {@code NAME:LINE:COL: message}. No GL: the thread that calls {@code loadAsset} (any); allocates
 * (load time). jME makes one loader per thread through the public no-argument constructor.
 */
public final class SceneAssetLoader implements AssetLoader {
    /**
     * What to register the loader for: the extension every {@link SceneKey} reports, and jME's
     * extension of a file named {@code NAME.jecosys.xml} (jME takes the last two parts of a name that
     * ends in {@code .xml}).
     */
    public static final String EXTENSION = "jecosys.xml";

    /** What jME calls to make a loader. */
    public SceneAssetLoader() {
    }

    /**
     * Reads and checks the scene and the images it names.
     *
     * @param info the located scene file
     * @return the {@link Scene}
     * @throws IOException        when the scene or an image cannot be read
     * @throws AssetLoadException when the scene is not valid, or an image is missing, outside the
     *                            scene's folder, too large or corrupt (the message lists every problem)
     */
    @Override
    public Object load(AssetInfo info) throws IOException {
        AssetKey<?> key = info.getKey();
        AssetManager manager = info.getManager();
        String folder = key.getFolder();
        ImageSource images = path -> {
            String name = folder + ImageSource.inFolder(path);
            AssetInfo image = manager.locateAsset(new AssetKey<>(name));
            if (image == null) {
                throw new IOException("image '" + path + "': no asset " + name + " next to the scene " + key.getName());
            }
            try (InputStream in = image.openStream()) {
                byte[] bytes = in.readNBytes((int) ImageSource.MAX_BYTES + 1);
                if (bytes.length > ImageSource.MAX_BYTES) {
                    throw new IOException("image '" + path + "': larger than " + ImageSource.MAX_BYTES + " bytes");
                }
                return bytes;
            }
        };
        try (InputStream in = info.openStream()) {
            return SceneFiles.read(in, key.getName(), images);
        } catch (SceneLoadException e) {
            throw new AssetLoadException(e.getMessage(), e);
        }
    }
}
