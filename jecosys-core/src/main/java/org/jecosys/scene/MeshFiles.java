package org.jecosys.scene;

import java.io.IOException;
import org.jecosys.plant.ComponentMesh;
import org.jecosys.plant.GltfMeshes;
import org.jecosys.plant.MeshDef;
import org.jecosys.plant.MeshGeometry;
import org.jecosys.plant.MeshMode;

/**
 * A {@code <component mesh>}'s glTF file, read while the scene is bound (once: the triangles checked
 * are the triangles built) through the scene's image source, so a mesh and its buffers obey the same
 * folder confinement as its images and come from a game's assets when they do. Each refusal is a
 * problem at the attribute, with its line and column. Load time; allocates.
 */
final class MeshFiles {
    private MeshFiles() {
    }

    /** The component's mesh, or null when it names none or a problem was reported. */
    static MeshDef mesh(SceneBinder binder, Values c) {
        String path = c.str("mesh");
        if (path == null) {
            for (String attr : new String[] {"meshMode", "meshScale"}) {
                if (c.present(attr)) {
                    binder.problem(c, attr, "attribute '" + attr + "' of <component>: there is no 'mesh' to apply it to");
                }
            }
            return null;
        }
        if (binder.source() == null) {
            binder.problem(c, "mesh", "attribute 'mesh' of <component>: '" + path + "' cannot be read: the scene was "
                    + "given without its folder");
            return null;
        }
        MeshGeometry g;
        try {
            g = GltfMeshes.read(path, binder.source()::read);
        } catch (IOException e) {
            binder.problem(c, "mesh", "attribute 'mesh' of <component>: " + e.getMessage());
            return null;
        }
        MeshMode mode = MeshDef.DEFAULT_MODE;
        for (MeshMode m : MeshMode.values()) {
            if (m.xmlName().equals(c.str("meshMode"))) {
                mode = m;
            }
        }
        MeshDef def = new MeshDef(path, mode, c.num("meshScale"), g);
        try {
            // what the build will do with it: a bound mesh needs a height to span the skeleton
            ComponentMesh.fromMesh(def, c.integer("segments"), c.num("length"));
        } catch (IllegalArgumentException e) {
            binder.problem(c, "mesh", "attribute 'mesh' of <component>: " + e.getMessage()
                    + "; a bound mesh stands along +Y (or use meshMode=\"rigid\")");
            return null;
        }
        return def;
    }
}
