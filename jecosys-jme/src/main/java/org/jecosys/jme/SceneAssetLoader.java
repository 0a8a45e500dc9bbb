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
 * assetManager.registerLoader(SceneAssetLoader.class, "xml");
 * Scene scene = assetManager.loadAsset(new SceneKey("Scenes/meadow.xml"));
 * }</pre>
 * The images the scene names (heightmaps, resource maps) are found the same way as the scene, relative
 * to its folder: {@code "Scenes/"} plus the path the scene writes, through
 * {@code assetManager.locateAsset}, so a scene on the classpath or in a {@code FileLocator} folder
 * takes its images from there. Image paths are confined to the scene's folder, as
 * {@link ImageSource#folder} does for files on disk: an absolute path, or {@code ..} that leads out of
 * it, is refused. jME picks a loader by the text after the first dot of the file name, so a file
 * named {@code x.meadow.xml} needs the loader registered for {@code "meadow.xml"}.
 *
 * <p>A scene that fails throws {@link AssetLoadException} whose message lists its problems as
 * {@code NAME:LINE:COL: message}. No GL: the thread that calls {@code loadAsset} (any); allocates
 * (load time). jME makes one loader per thread through the public no-argument constructor.
 */
public final class SceneAssetLoader implements AssetLoader {
    /** The extension of scene files, for {@code registerLoader}. */
    public static final String EXTENSION = "xml";

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
