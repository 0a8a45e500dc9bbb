package org.jecosys.scene;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.jecosys.math.Rgb;
import org.jecosys.plant.ComponentDef;
import org.jecosys.plant.ComponentShape;
import org.jecosys.plant.ComponentType;
import org.jecosys.terrain.ImageFiles;

/**
 * Binds a {@code <component>} of a species ({@link SceneBinder}'s part for components): its attachment
 * to another component of the species, its per-level segments, its texture (checked as an image, at most
 * {@link org.jecosys.plant.PlantTextures#MAX_SIDE} a side) and its glTF mesh ({@link MeshFiles}). Each
 * problem is reported at its attribute. Load time; allocates.
 */
final class ComponentBinder {
    private ComponentBinder() {
    }

    @SuppressWarnings("unchecked")
    static ComponentDef component(SceneBinder binder, Values c, Set<String> compIds, int lodCount) {
        String attach = c.str("attachTo");
        if (attach != null && (!compIds.contains(attach) || attach.equals(c.str("id")))) {
            List<String> others = new ArrayList<>(compIds);
            others.remove(c.str("id"));
            others.sort(null);
            binder.problem(c, "attachTo", "attribute 'attachTo' of <component>: '" + attach
                    + "' is not another component of this species" + Names.didYouMean(attach, others)
                    + (others.isEmpty() ? "" : "; components: " + String.join(", ", others)));
            return null;
        }
        if (attach == null && c.num("attachAt") != 1) {
            binder.problem(c, "attachAt", "attribute 'attachAt' of <component>: " + c.num("attachAt") + " needs attachTo "
                    + "(the component it sits on); a component on the ground stands at its base");
            return null;
        }
        List<Integer> lodSegments = (List<Integer>) c.get("lodSegments");
        if (lodSegments == null) {
            return null;
        }
        if (lodSegments.size() != lodCount) {
            binder.problem(c, "lodSegments", "attribute 'lodSegments' of <component>: " + lodSegments.size()
                    + " values given; the species has " + lodCount + " <lod> elements, one value each");
            return null;
        }
        for (int v : lodSegments) {
            if (v > c.integer("segments")) {
                binder.problem(c, "lodSegments", "attribute 'lodSegments' of <component>: " + v + " exceeds segments="
                        + c.integer("segments"));
                return null;
            }
        }
        return binder.make(c, () -> new ComponentDef(c.str("id"), SceneBinder.byXml(ComponentType.values(), c.str("type")),
                SceneBinder.byXml(ComponentShape.values(), c.str("shape")), c.integer("count"), attach, c.integer("segments"),
                c.num("length"), c.num("baseWidth"), c.num("tipWidth"), c.num("curvature"), c.num("twist"),
                c.num("tilt"), c.num("mass"), c.num("stiffness"), c.num("responseTime"), c.num("dragArea"),
                (Rgb) c.get("colour"), lodSegments, texture(binder, c), MeshFiles.mesh(binder, c), c.num("attachAt")));
    }

    /** The component's texture, checked as an image and against {@link org.jecosys.plant.PlantTextures#MAX_SIDE}. */
    private static String texture(SceneBinder binder, Values c) {
        String path = c.str("texture");
        int before = binder.images.size();
        binder.checkFile(c, "texture", path);
        if (binder.images.size() > before) {
            ImageFiles.Size size = binder.images.get(binder.images.size() - 1).size();
            int most = org.jecosys.plant.PlantTextures.MAX_SIDE;
            if (size.width() > most || size.height() > most) {
                binder.problem(c, "texture", "attribute 'texture' of <component>: '" + path + "' is " + size.width() + "x"
                        + size.height() + " pixels; a texture is at most " + most + " pixels a side");
            }
        }
        return path;
    }

}
