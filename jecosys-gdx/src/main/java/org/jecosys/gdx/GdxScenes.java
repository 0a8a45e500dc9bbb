package org.jecosys.gdx;

import com.badlogic.gdx.files.FileHandle;
import com.badlogic.gdx.utils.GdxRuntimeException;
import java.io.IOException;
import java.io.InputStream;
import org.jecosys.math.Require;
import org.jecosys.scene.Scene;
import org.jecosys.scene.SceneFiles;
import org.jecosys.scene.SceneLoadException;
import org.jecosys.terrain.ImageSource;

/**
 * Scene files as libGDX {@link FileHandle}s, of any {@code FileType} (classpath, internal, local,
 * external, absolute): the scene is read through {@link FileHandle#read()}, and the images it names
 * (heightmaps, resource maps) through {@link FileHandle#sibling(String)} of the scene file, so they
 * resolve the same way as the scene (an internal scene's images are internal files, found on the
 * classpath when they are not in the working directory).
 *
 * <p>Image paths are confined to the scene file's folder, as {@link ImageSource#folder} does for files
 * on disk: an absolute path, or {@code ..} that leads out of the scene's folder, is refused with the
 * reason. Any thread (the asset manager's loader thread included); no GL; allocates (load time).
 */
public final class GdxScenes {
    private GdxScenes() {
    }

    /**
     * Reads and checks a scene file and the images it names; problems are reported under the
     * handle's {@link FileHandle#path()}, as {@code PATH:LINE:COL: message}. Any thread; allocates.
     *
     * @param sceneFile the scene's XML
     * @return the scene, with the bytes of its images as they were checked
     * @throws SceneLoadException when the file is not a valid scene, or an image it names is missing,
     *                            outside its folder, too large or corrupt
     * @throws GdxRuntimeException when the file itself cannot be opened (libGDX's "File not found")
     */
    public static Scene read(FileHandle sceneFile) throws SceneLoadException {
        Require.nonNull("sceneFile", sceneFile);
        try (InputStream in = sceneFile.read()) {
            return SceneFiles.read(in, sceneFile.path(), images(sceneFile));
        } catch (IOException closing) {
            throw new GdxRuntimeException("cannot close " + sceneFile.path() + " (" + sceneFile.type() + ")", closing);
        }
    }

    /**
     * The images of a scene file: each path the scene writes, relative to the scene's folder, read
     * whole from the scene's {@link FileHandle#sibling(String) sibling}. Any thread; allocates.
     *
     * @param sceneFile the scene's XML (not its folder)
     * @return a source that reads the images next to {@code sceneFile}, of the same file type
     */
    public static ImageSource images(FileHandle sceneFile) {
        Require.nonNull("sceneFile", sceneFile);
        return path -> {
            FileHandle image = sceneFile.sibling(ImageSource.inFolder(path));
            if (image.isDirectory()) {
                throw new IOException("image '" + path + "': " + image.path() + " (" + image.type() + ") is a folder");
            }
            if (!image.exists()) {
                throw new IOException("image '" + path + "': no file " + image.path() + " (" + image.type()
                        + ") next to the scene " + sceneFile.path());
            }
            try (InputStream in = image.read()) {
                byte[] bytes = in.readNBytes((int) ImageSource.MAX_BYTES + 1);
                if (bytes.length > ImageSource.MAX_BYTES) {
                    throw new IOException("image '" + path + "': larger than " + ImageSource.MAX_BYTES + " bytes");
                }
                return bytes;
            } catch (GdxRuntimeException e) {
                throw new IOException("image '" + path + "': " + e.getMessage(), e);
            }
        };
    }
}
