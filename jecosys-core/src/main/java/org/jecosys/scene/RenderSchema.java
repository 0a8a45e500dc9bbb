package org.jecosys.scene;

import static org.jecosys.scene.AttrType.COLOUR;
import static org.jecosys.scene.SceneSchema.angle;
import static org.jecosys.scene.SceneSchema.bool;
import static org.jecosys.scene.SceneSchema.enumeration;
import static org.jecosys.scene.SceneSchema.integer;
import static org.jecosys.scene.SceneSchema.num;
import static org.jecosys.scene.SceneSchema.words;

import java.util.List;
import java.util.function.Function;

/**
 * The {@code <render>} part of the scene format ({@link SceneSchema}): presentation settings, the
 * light, the colour patches and the ground cover. Immutable after class initialisation; any thread.
 */
final class RenderSchema {
    private RenderSchema() {
    }

    /** {@return the {@code <render>} element and its children} */
    static ElementSpec render() {
        RenderDef.Light ld = RenderDef.Light.DEFAULT;
        Function<Object, RenderDef.Light> li = d -> (RenderDef.Light) d;
        ElementSpec light = new ElementSpec("light", "Sun, sky gradient, ambient light, contact shadow and aerial "
                + "perspective (presentation only).")
                .attr(angle("sunAzimuth", "Compass angle of the sun: the direction toward it is (cos el cos az, "
                        + "sin el, cos el sin az), so 0 is +X and 90 is +Z.")
                        .range(-RenderDef.Light.MAX_AZIMUTH_DEGREES, RenderDef.Light.MAX_AZIMUTH_DEGREES)
                        .def(ld.sunAzimuth()).get(d -> li.apply(d).sunAzimuth()))
                .attr(angle("sunElevation", "Height of the sun above the horizon.")
                        .range(0, RenderDef.Light.MAX_ELEVATION_DEGREES).def(ld.sunElevation())
                        .get(d -> li.apply(d).sunElevation()))
                .attr(AttrSpec.of("sunColour", COLOUR, "", "Colour of the sunlight.").def(ld.sunColour())
                        .get(d -> li.apply(d).sunColour()))
                .attr(num("sunIntensity", "", "Multiplier of the sun colour.").range(0, RenderDef.Light.MAX_INTENSITY)
                        .def(ld.sunIntensity()).get(d -> li.apply(d).sunIntensity()))
                .attr(AttrSpec.of("skyZenith", COLOUR, "", "Sky colour straight up; the render's sky is the "
                        + "horizon.").def(ld.skyZenith()).get(d -> li.apply(d).skyZenith()))
                .attr(AttrSpec.of("ambient", COLOUR, "", "Sky light on an upward-facing surface (colour times "
                        + "strength).").def(ld.ambient()).get(d -> li.apply(d).ambient()))
                .attr(num("contactShadow", "", "How much darker fully occluded ground under plants is (0 none).")
                        .range(0, 1).def(ld.contactShadow()).get(d -> li.apply(d).contactShadow()))
                .attr(num("fogStart", "metres", "Distance where the haze toward the horizon colour begins.")
                        .range(0, RenderDef.Light.MAX_FOG).def(ld.fogStart()).get(d -> li.apply(d).fogStart()))
                .attr(num("fogEnd", "metres", "Distance of full haze; above fogStart.")
                        .range(0, RenderDef.Light.MAX_FOG).def(ld.fogEnd()).get(d -> li.apply(d).fogEnd()))
                .attr(num("sheen", "", "Strength of the wind's sheen: a blade bent by the wind brightens toward its "
                        + "pale, sky-lit side, so gusts read from afar as travelling bands of light (0 turns it off).")
                        .range(0, RenderDef.Light.MAX_SHEEN).def(ld.sheen()).get(d -> li.apply(d).sheen()))
                .attr(num("shadows", "", "Strength of the plants' sun shadows on the ground: the share of the sun's "
                        + "direct light a fully shadowed point loses (the plants at rest, from the sun's direction; "
                        + "0 turns them off).").range(0, 1).def(ld.shadows()).get(d -> li.apply(d).shadows()))
                .attr(num("clouds", "", "How much of the sky fair-weather clouds cover, lit by the sun and thinning "
                        + "into the haze at the horizon (0 for a clear sky).").range(0, 1).def(ld.clouds())
                        .get(d -> li.apply(d).clouds()));
        RenderDef.Patches pd = RenderDef.Patches.DEFAULT;
        ElementSpec patches = new ElementSpec("patches", "Large healthy/dry colour patches over the ground and "
                + "the plants, from seeded noise (presentation only).")
                .attr(num("scale", "metres", "Feature size of the noise.")
                        .range(RenderDef.Patches.MIN_SCALE, RenderDef.Patches.MAX_SCALE).def(pd.scale())
                        .get(d -> ((RenderDef.Patches) d).scale()))
                .attr(num("strength", "", "How far the driest patches go toward dry (0 turns patches off).")
                        .range(0, 1).def(pd.strength()).get(d -> ((RenderDef.Patches) d).strength()))
                .attr(integer("seed", "Seed of the noise.").range(Integer.MIN_VALUE, Integer.MAX_VALUE)
                        .def(pd.seed()).get(d -> ((RenderDef.Patches) d).seed()));

        RenderDef rd = RenderDef.defaults();
        return new ElementSpec("render", "Presentation settings.")
                .attr(integer("width", "Window or image width, pixels.").range(16, 8192).def(rd.width())
                        .get(d -> ((RenderDef) d).width()))
                .attr(integer("height", "Window or image height, pixels.").range(16, 8192).def(rd.height())
                        .get(d -> ((RenderDef) d).height()))
                .attr(AttrSpec.of("sky", COLOUR, "", "Horizon and fog colour (the sky gradient runs from it to "
                        + "the light's skyZenith).").def(rd.sky())
                        .get(d -> ((RenderDef) d).sky()))
                .attr(num("lodTransition", "metres", "Band over which two levels of detail are dithered.")
                        .range(0, 10).def(rd.lodTransition()).get(d -> ((RenderDef) d).lodTransition()))
                .attr(enumeration("terrainTint", words(RenderDef.Tint.values(), RenderDef.Tint::xmlName),
                        "Which resource map tints the terrain.").def("none")
                        .get(d -> ((RenderDef) d).terrainTint().xmlName()))
                .attr(bool("showField", "Force-field overlay visible at start (paper Figure 2).").def(false)
                        .get(d -> ((RenderDef) d).showField()))
                .attr(bool("showWind", "Wind-vector overlay visible at start (paper Figure 3).").def(false)
                        .get(d -> ((RenderDef) d).showWind()))
                .attr(enumeration("antialiasing", List.of("1", "2", "4", "8"), "Samples per pixel of the viewer's "
                        + "window and of headless images (multisample anti-aliasing); 1 turns it off.")
                        .def(Integer.toString(RenderDef.DEFAULT_ANTIALIASING))
                        .get(d -> Integer.toString(((RenderDef) d).antialiasing())))
                .child(light, 0, 1, d -> List.of(((RenderDef) d).light()))
                .child(patches, 0, 1, d -> List.of(((RenderDef) d).patches()))
                .child(groundCover(), 0, 1, d -> ((RenderDef) d).groundCover().enabled()
                        ? List.of(((RenderDef) d).groundCover()) : List.of());

    }

    /** {@return the {@code <groundCover>} element} */
    private static ElementSpec groundCover() {
        RenderDef.GroundCover gd = RenderDef.GroundCover.NONE;
        Function<Object, RenderDef.GroundCover> g = d -> (RenderDef.GroundCover) d;
        return new ElementSpec("groundCover", "A dense short layer of vegetation where the plants grow, so that no "
                + "bare soil shows between them: short blades near the eye, the ground in the cover's colour beyond "
                + "(presentation only). Without it the ground between the plants is bare.")
                .attr(num("amount", "", "How fully the cover hides the soil where plants grow (0 turns it off).")
                        .range(0, 1).def(1.0).get(d -> g.apply(d).amount()))
                .attr(num("height", "metres", "Height of the near blades.")
                        .range(RenderDef.GroundCover.MIN_HEIGHT, RenderDef.GroundCover.MAX_HEIGHT).def(gd.height())
                        .get(d -> g.apply(d).height()))
                .attr(num("density", "per square metre", "Near blades per square metre.")
                        .range(0, RenderDef.GroundCover.MAX_DENSITY).def(gd.density()).get(d -> g.apply(d).density()))
                .attr(num("reach", "metres", "Distance from the eye out to which near blades are drawn (0: the "
                        + "ground's colour alone).").range(0, RenderDef.GroundCover.MAX_REACH).def(gd.reach())
                        .get(d -> g.apply(d).reach()))
                .attr(num("spread", "metres", "Distance from a plant over which it brings cover.")
                        .range(RenderDef.GroundCover.MIN_SPREAD, RenderDef.GroundCover.MAX_SPREAD).def(gd.spread())
                        .get(d -> g.apply(d).spread()))
                .attr(AttrSpec.of("colour", COLOUR, "", "Colour of healthy cover.").def(gd.colour())
                        .get(d -> g.apply(d).colour()))
                .attr(AttrSpec.of("dryColour", COLOUR, "", "Colour of dry cover (dry patches).").def(gd.dryColour())
                        .get(d -> g.apply(d).dryColour()));
    }
}
