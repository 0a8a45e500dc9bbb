package org.jecosys.plant;

import org.jecosys.math.Require;

/**
 * A component drawn as a mesh from a glTF 2.0 file instead of its strip or fan, at the levels of
 * detail that draw all its segments (the lower levels keep the strip and lines of the component's
 * own widths; see {@link ComponentMesh#fromMesh}). Immutable; any thread.
 *
 * @param path     the file as the scene writes it (relative to the scene's folder), not blank
 * @param mode     how the mesh follows the skeleton
 * @param scale    uniform scale of the mesh's coordinates (glTF units are metres), in [1e-3, 1e3];
 *                 a {@link MeshMode#BOUND} mesh is first scaled so that its height is the
 *                 component's length, then its X and Z by this factor
 * @param geometry the triangles read from the file
 */
public record MeshDef(String path, MeshMode mode, double scale, MeshGeometry geometry) {
    /** Smallest {@link #scale()}. */
    public static final double MIN_SCALE = 1e-3;
    /** Largest {@link #scale()}. */
    public static final double MAX_SCALE = 1e3;
    /** Default {@link #mode()} in scene files. */
    public static final MeshMode DEFAULT_MODE = MeshMode.BOUND;
    /** Default {@link #scale()} in scene files: as modelled. */
    public static final double DEFAULT_SCALE = 1;

    /**
     * Checks the components.
     *
     * @param path     not blank
     * @param mode     not null
     * @param scale    in [1e-3, 1e3]
     * @param geometry not null
     * @throws IllegalArgumentException when a component is null, blank or out of range
     */
    public MeshDef {
        Require.nonNull("path", path);
        if (path.isBlank()) {
            throw new IllegalArgumentException("path must not be blank");
        }
        Require.nonNull("mode", mode);
        Require.range("scale", scale, MIN_SCALE, MAX_SCALE);
        Require.nonNull("geometry", geometry);
    }
}
