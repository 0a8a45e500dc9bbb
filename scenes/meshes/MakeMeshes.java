import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.jecosys.plant.GltfWriter;
import org.jecosys.plant.MeshGeometry;

/**
 * Makes the glTF meshes of scenes/textured.xml, deterministically, with the library's own writer:
 * mvn -q -pl jecosys-core compile && java -cp jecosys-core/target/classes scenes/meshes/MakeMeshes.java scenes/meshes
 *
 * flower-head.glb: a seed head, a low dome 1 unit across (radius 0.5) over a flat rim, rising 0.18 at
 * its centre, in 6 rings of 20 vertices around a centre vertex; its texture coordinates map the
 * flower-head image radially (its centre at the dome's top, its rim at the image's edge). Modelled
 * along +Y with its base at the origin: a rigid mesh on a stalk's tip (meshScale sets its size).
 * Part of JEcoSys, under the project's licence.
 */
public final class MakeMeshes {
    private static final int RINGS = 6;
    private static final int AROUND = 20;

    private MakeMeshes() {
    }

    public static void main(String[] args) throws IOException {
        Path out = Path.of(args.length > 0 ? args[0] : ".");
        Files.createDirectories(out);
        Files.write(out.resolve("flower-head.glb"), GltfWriter.glb(head()));
    }

    static MeshGeometry head() {
        int n = 1 + RINGS * AROUND;
        float[] pos = new float[3 * n];
        float[] nrm = new float[3 * n];
        float[] uv = new float[2 * n];
        put(pos, nrm, uv, 0, 0, 0);
        for (int r = 1; r <= RINGS; r++) {
            double f = r / (double) RINGS;
            for (int j = 0; j < AROUND; j++) {
                double a = 2 * Math.PI * j / AROUND;
                put(pos, nrm, uv, 1 + (r - 1) * AROUND + j, f * Math.cos(a), f * Math.sin(a));
            }
        }
        int[] idx = new int[3 * (AROUND + 2 * AROUND * (RINGS - 1))];
        int w = 0;
        for (int j = 0; j < AROUND; j++) {
            idx[w++] = 0;
            idx[w++] = 1 + j;
            idx[w++] = 1 + (j + 1) % AROUND;
        }
        for (int r = 1; r < RINGS; r++) {
            int in = 1 + (r - 1) * AROUND;
            int ou = in + AROUND;
            for (int j = 0; j < AROUND; j++) {
                int j1 = (j + 1) % AROUND;
                idx[w++] = in + j;
                idx[w++] = ou + j;
                idx[w++] = ou + j1;
                idx[w++] = in + j;
                idx[w++] = ou + j1;
                idx[w++] = in + j1;
            }
        }
        return new MeshGeometry(pos, nrm, uv, idx);
    }

    /** Vertex v at (x, z) on the unit disc (radius f = |(x, z)|): the dome's height and normal, radial uv. */
    private static void put(float[] pos, float[] nrm, float[] uv, int v, double x, double z) {
        double f2 = x * x + z * z;
        double h = 0.18 * (1 - f2);
        pos[3 * v] = (float) (0.5 * x);
        pos[3 * v + 1] = (float) h;
        pos[3 * v + 2] = (float) (0.5 * z);
        // the dome y = 0.18 (1 - 4 (X^2 + Z^2)) with X = 0.5 x: gradient (-1.44 X, 1, -1.44 Z)
        double nx = 1.44 * 0.5 * x;
        double nz = 1.44 * 0.5 * z;
        double l = Math.sqrt(nx * nx + 1 + nz * nz);
        nrm[3 * v] = (float) (nx / l);
        nrm[3 * v + 1] = (float) (1 / l);
        nrm[3 * v + 2] = (float) (nz / l);
        uv[2 * v] = (float) (0.5 + 0.5 * x);
        uv[2 * v + 1] = (float) (0.5 - 0.5 * z);
    }
}
