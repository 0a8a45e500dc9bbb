package org.jecosys.scene;

import org.jecosys.math.Rgb;

/**
 * Presentation settings of a scene. The application passes them to the renderer. Immutable; any thread.
 *
 * @param width         default window or image width, pixels, in [16, 8192]
 * @param height        default window or image height, pixels, in [16, 8192]
 * @param sky           horizon and fog colour (the sky gradient runs from it to {@link Light#skyZenith()})
 * @param lodTransition width of the band over which two levels of detail are dithered, metres, in [0, 10]
 * @param terrainTint   which resource map tints the terrain
 * @param showField     whether the force-field quadtree overlay starts visible (paper Figure 2)
 * @param showWind      whether the wind-vector overlay starts visible (paper Figure 3)
 * @param light         sun, sky gradient, ambient light, contact shadow and aerial perspective
 * @param patches       large-scale healthy/dry colour patches over the ground and the plants
 * @param antialiasing  samples per pixel of the viewer's window and of headless images: 1 (none), 2, 4
 *                      or 8; thin parts of plants are drawn with their coverage as alpha, which
 *                      multisampling turns into partly covered pixels
 * @param groundCover   the dense short layer that hides the soil where the scene's plants grow
 *                      ({@link GroundCover#NONE}: bare ground, as in the paper's scenes)
 */
public record RenderDef(int width, int height, Rgb sky, double lodTransition, Tint terrainTint, boolean showField,
                        boolean showWind, Light light, Patches patches, int antialiasing, GroundCover groundCover) {
    /** Default {@link #antialiasing()}: 4 samples per pixel. */
    public static final int DEFAULT_ANTIALIASING = 4;

    /**
     * Sun, sky and atmosphere of a scene: presentation only, never read by the simulation. Immutable;
     * any thread.
     *
     * @param sunAzimuth    compass angle of the sun, radians, in [-2 pi, 2 pi]: the direction toward the
     *                      sun is (cos el cos az, sin el, cos el sin az), so 0 is +X and pi/2 is +Z
     * @param sunElevation  height of the sun above the horizon, radians, in [0, pi/2]
     * @param sunColour     colour of the sunlight
     * @param sunIntensity  multiplier of the sun colour, in [0, 4] (radiance = sunColour x sunIntensity)
     * @param skyZenith     sky colour straight up (the render's {@code sky} is the horizon and fog colour)
     * @param ambient       sky light reaching an upward-facing surface, colour times strength
     * @param contactShadow how much darker fully occluded ground under plants is, in [0, 1]
     * @param fogStart      distance where the aerial perspective (haze toward the horizon colour) begins,
     *                      metres, &gt;= 0
     * @param fogEnd        distance of full haze, metres, &gt; fogStart
     * @param sheen         strength of the wind's sheen: how much a blade bent by the wind brightens
     *                      toward its pale, sky-lit side, in [0, 2]; 0 turns it off
     * @param shadows       strength of the plants' sun shadows on the ground: the share of the sun's direct
     *                      light a fully shadowed point loses, in [0, 1]; 0 (the default) turns them off
     * @param clouds        how much of the sky fair-weather clouds cover, in [0, 1]; 0 (the default): a clear sky
     */
    public record Light(double sunAzimuth, double sunElevation, Rgb sunColour, double sunIntensity, Rgb skyZenith,
                        Rgb ambient, double contactShadow, double fogStart, double fogEnd, double sheen,
                        double shadows, double clouds) {
        /** Largest sun azimuth magnitude, degrees (the Def holds radians). */
        public static final double MAX_AZIMUTH_DEGREES = 360;
        /** Largest sun elevation, degrees (the Def holds radians). */
        public static final double MAX_ELEVATION_DEGREES = 90;
        /** Largest sun intensity. */
        public static final double MAX_INTENSITY = 4;
        /** Largest fog distance, metres. */
        public static final double MAX_FOG = 100_000;
        /** Largest {@link #sheen()}. */
        public static final double MAX_SHEEN = 2;

        /**
         * Checks the components.
         *
         * @param sunAzimuth    radians, in [-2 pi, 2 pi]
         * @param sunElevation  radians, in [0, pi/2]
         * @param sunColour     not null
         * @param sunIntensity  in [0, 4]
         * @param skyZenith     not null
         * @param ambient       not null
         * @param contactShadow in [0, 1]
         * @param fogStart      metres, in [0, 100000]
         * @param fogEnd        metres, in (fogStart, 100000]
         * @param sheen         in [0, 2]
         * @param shadows       in [0, 1]
         * @param clouds        in [0, 1]
         * @throws IllegalArgumentException when a component is null or out of range
         */
        public Light {
            RenderDefChecks.light(sunAzimuth, sunElevation, sunColour, sunIntensity, skyZenith, ambient, contactShadow,
                    fogStart, fogEnd, sheen, shadows, clouds);
        }

        /**
         * A clear sky ({@link #clouds()} 0). Values as the canonical constructor's.
         *
         * @param sunAzimuth    radians
         * @param sunElevation  radians
         * @param sunColour     not null
         * @param sunIntensity  in [0, 4]
         * @param skyZenith     not null
         * @param ambient       not null
         * @param contactShadow in [0, 1]
         * @param fogStart      metres
         * @param fogEnd        metres, above fogStart
         * @param sheen         in [0, 2]
         * @param shadows       in [0, 1]
         */
        public Light(double sunAzimuth, double sunElevation, Rgb sunColour, double sunIntensity, Rgb skyZenith,
                     Rgb ambient, double contactShadow, double fogStart, double fogEnd, double sheen, double shadows) {
            this(sunAzimuth, sunElevation, sunColour, sunIntensity, skyZenith, ambient, contactShadow, fogStart, fogEnd,
                    sheen, shadows, 0);
        }

        /**
         * The defaults: the sun at azimuth 135 degrees, elevation 50 degrees (high, behind and to the left
         * of a camera looking along -Z, as the scenes' start cameras do), warm white at intensity 0.8, a
         * deeper blue zenith, a cool ambient of about 0.45, contact shadow 0.5, haze from 20 m to 150 m,
         * the wind's sheen at 1, no sun shadows and a clear sky.
         */
        public static final Light DEFAULT = new Light(Math.toRadians(135), Math.toRadians(50),
                new Rgb(1f, 0.95f, 0.85f), 0.8, new Rgb(0.30f, 0.50f, 0.85f), new Rgb(0.42f, 0.46f, 0.52f), 0.5,
                20, 150, 1, 0);
    }

    /**
     * Large-scale colour patches: a seeded noise over the ground mixes healthy and dry colour (plants in
     * dry patches turn toward straw, the soil lighter). Presentation only. Immutable; any thread.
     *
     * @param scale    feature size of the noise, metres, in [0.5, 1000]
     * @param strength how far the driest patches go from healthy to dry, in [0, 1]; 0 turns patches off
     * @param seed     seed of the noise (any int)
     */
    public record Patches(double scale, double strength, int seed) {
        /** Smallest patch scale, metres. */
        public static final double MIN_SCALE = 0.5;
        /** Largest patch scale, metres. */
        public static final double MAX_SCALE = 1000;

        /**
         * Checks the components.
         *
         * @param scale    metres, in [0.5, 1000]
         * @param strength in [0, 1]
         * @param seed     any int
         * @throws IllegalArgumentException when a component is out of range
         */
        public Patches {
            RenderDefChecks.patches(scale, strength);
        }

        /** The defaults: 12 m patches at strength 0.3, seed 1. */
        public static final Patches DEFAULT = new Patches(12, 0.3, 1);
    }

    /**
     * Ground cover: a dense short layer of vegetation where the scene's plants grow, so that no bare soil
     * shows between them. Near the camera it is drawn as short instanced blades bending with the wind;
     * beyond, and under them, the ground itself takes the cover's colour with a fine grain of blades and
     * dry patches. It grows where plants stand: its amount at a point rises with the number of plants
     * within {@code spread} metres. Presentation only (the simulation never reads it); counted as
     * vegetation, so a renderer told to leave the plants out leaves it out too. Immutable; any thread.
     *
     * @param amount    how fully the cover hides the soil where plants grow, in [0, 1]; 0 turns it off
     * @param height    height of the near blades, metres, in [0.005, 0.5]
     * @param density   near blades per square metre, in [0, 20000]
     * @param reach     distance from the eye out to which near blades are drawn, metres, in [0, 50]
     *                  (0: the ground's colour alone)
     * @param spread    distance from a plant over which it brings cover, metres, in [0.1, 20]
     * @param colour    colour of healthy cover
     * @param dryColour colour of dry cover (dry patches, tips)
     */
    public record GroundCover(double amount, double height, double density, double reach, double spread,
                              Rgb colour, Rgb dryColour) {
        /** Largest {@link #height()}, metres. */
        public static final double MAX_HEIGHT = 0.5;
        /** Smallest {@link #height()}, metres. */
        public static final double MIN_HEIGHT = 0.005;
        /** Largest {@link #density()}, blades per square metre. */
        public static final double MAX_DENSITY = 20_000;
        /** Largest {@link #reach()}, metres. */
        public static final double MAX_REACH = 50;
        /** Smallest {@link #spread()}, metres. */
        public static final double MIN_SPREAD = 0.1;
        /** Largest {@link #spread()}, metres. */
        public static final double MAX_SPREAD = 20;
        /** Side of the square ground tiles the near blades are drawn in, metres. */
        public static final double BLADE_TILE = 1;
        /** Most tiles of near blades drawn for one view in a frame. */
        public static final int MAX_BLADE_TILES = 4096;
        /**
         * Most near blades one view may submit in a frame, wherever its camera stands: the scene check
         * refuses a cover whose {@link #bladesPerViewAtMost} exceeds it (at density 20,000 and reach
         * 50 m a 960 x 540 frame took 28 s and 1 GB on a software renderer), and a renderer given more
         * at run time thins every tile's blades to stay within it. The shipped meadow asks for 695,000.
         */
        public static final long MAX_BLADES_PER_VIEW = 4_000_000;

        /**
         * Checks the components.
         *
         * @param amount    in [0, 1]
         * @param height    metres, in [0.005, 0.5]
         * @param density   blades per square metre, in [0, 20000]
         * @param reach     metres, in [0, 50]
         * @param spread    metres, in [0.1, 20]
         * @param colour    not null
         * @param dryColour not null
         * @throws IllegalArgumentException when a component is null or out of range
         */
        public GroundCover {
            RenderDefChecks.groundCover(amount, height, density, reach, spread, colour, dryColour);
        }

        /** {@return whether there is any cover to draw ({@link #amount()} above 0)} */
        public boolean enabled() {
            return amount > 0;
        }

        /** {@return near blades per ground tile ({@link #BLADE_TILE} square): the density times its area, whole blades} */
        public int bladesPerTile() {
            return (int) Math.min(density * BLADE_TILE * BLADE_TILE, 65_536);
        }

        /**
         * The most near blades drawn for one view in a frame, wherever its camera: {@link #bladesPerTile}
         * times the tiles that can lie within {@link #reach()} of the eye (every such tile lies within
         * reach plus a tile's diagonal, so at most that disc's area over a tile's), at most
         * {@link #MAX_BLADE_TILES} and the terrain's tiles. 0 when there is no cover or no reach. Any
         * thread; no allocation.
         *
         * @param sizeX the terrain's extent along X, metres, &gt; 0
         * @param sizeZ the terrain's extent along Z, metres, &gt; 0
         * @return blades, at most {@link #MAX_BLADE_TILES} x 65,536
         */
        public long bladesPerViewAtMost(double sizeX, double sizeZ) {
            if (!enabled() || reach <= 0) {
                return 0;
            }
            double r = reach + BLADE_TILE * Math.sqrt(2);
            double near = Math.floor(Math.PI * r * r / (BLADE_TILE * BLADE_TILE));
            double ground = Math.ceil(sizeX / BLADE_TILE) * Math.ceil(sizeZ / BLADE_TILE);
            long tiles = (long) Math.min(MAX_BLADE_TILES, Math.min(near, ground));
            return tiles * bladesPerTile();
        }

        /**
         * No cover: bare ground between the plants (amount 0; the other values are the element's
         * defaults: 6 cm blades, 2500 per square metre to 8 m, spreading 1.5 m from each plant, a
         * meadow green drying to straw).
         */
        public static final GroundCover NONE = new GroundCover(0, 0.06, 2500, 8, 1.5, new Rgb(0.30f, 0.50f, 0.16f),
                new Rgb(0.62f, 0.56f, 0.30f));
    }

    /** Which map tints the terrain. */
    public enum Tint {
        /** Plain terrain colour. */
        NONE("none"),
        /** Blue where water is high. */
        WATER("water"),
        /** Brown-green by nutrient level. */
        NUTRIENTS("nutrients");

        private final String xmlName;

        Tint(String xmlName) {
            this.xmlName = xmlName;
        }

        /** {@return the attribute value used in scene files, e.g. {@code "water"}} */
        public String xmlName() {
            return xmlName;
        }
    }

    /**
     * Checks the components.
     *
     * @param width         default width, pixels, in [16, 8192]
     * @param height        default height, pixels, in [16, 8192]
     * @param sky           background colour, not null
     * @param lodTransition dithering band width, metres, in [0, 10]
     * @param terrainTint   terrain tint, not null
     * @param showField     whether the quadtree overlay starts visible
     * @param showWind      whether the wind-vector overlay starts visible
     * @param light         sun, sky and atmosphere, not null
     * @param patches       colour patches, not null
     * @param antialiasing  samples per pixel: 1, 2, 4 or 8
     * @param groundCover   ground cover, not null ({@link GroundCover#NONE} for none)
     * @throws IllegalArgumentException when a component is null or out of range
     */
    public RenderDef {
        RenderDefChecks.render(width, height, sky, lodTransition, terrainTint, light, patches, antialiasing,
                groundCover);
    }

    /**
     * A copy with other light settings. Any thread; allocates.
     *
     * @param light the new light, not null
     * @return the copy
     */
    public RenderDef withLight(Light light) {
        return new RenderDef(width, height, sky, lodTransition, terrainTint, showField, showWind, light, patches,
                antialiasing, groundCover);
    }

    /**
     * A copy with other ground cover. Any thread; allocates.
     *
     * @param groundCover the new ground cover, not null
     * @return the copy
     */
    public RenderDef withGroundCover(GroundCover groundCover) {
        return new RenderDef(width, height, sky, lodTransition, terrainTint, showField, showWind, light, patches,
                antialiasing, groundCover);
    }

    /**
     * {@return the scene schema's defaults, {@code builder().build()}: 1280x720, light blue horizon, a 1 m
     * transition band, no tint, overlays hidden, the default light and patches, 4x anti-aliasing, no
     * ground cover} Any thread; allocates.
     */
    public static RenderDef defaults() {
        return builder().build();
    }

    /**
     * A builder with every value at the scene schema's default (see {@link #defaults()}): what an empty
     * {@code <render/>} element loads as. Any thread; allocates.
     *
     * @return a new builder
     */
    public static Builder builder() {
        return new Builder();
    }

    /**
     * A builder holding every value of this def, to change a few. Any thread; allocates.
     *
     * @return a new builder
     */
    public Builder toBuilder() {
        return new Builder().size(width, height).sky(sky).lodTransition(lodTransition).terrainTint(terrainTint)
                .showField(showField).showWind(showWind).light(light).patches(patches).antialiasing(antialiasing)
                .groundCover(groundCover);
    }

    /**
     * Fluent builder of a {@link RenderDef} with the scene schema's defaults (see
     * {@link RenderDef#builder}); values are checked by {@link #build()}. One thread; allocates.
     */
    public static final class Builder {
        private int width = 1280;
        private int height = 720;
        private Rgb sky = new Rgb(0.62f, 0.76f, 0.92f);
        private double lodTransition = 1;
        private Tint terrainTint = Tint.NONE;
        private boolean showField = false;
        private boolean showWind = false;
        private Light light = Light.DEFAULT;
        private Patches patches = Patches.DEFAULT;
        private int antialiasing = DEFAULT_ANTIALIASING;
        private GroundCover groundCover = GroundCover.NONE;

        private Builder() {
        }

        /**
         * Sets the default window or image size (default 1280 x 720).
         *
         * @param width  pixels, in [16, 8192]
         * @param height pixels, in [16, 8192]
         * @return this builder
         */
        public Builder size(int width, int height) {
            this.width = width;
            this.height = height;
            return this;
        }

        /**
         * Sets the horizon and fog colour (default light blue).
         *
         * @param sky not null
         * @return this builder
         */
        public Builder sky(Rgb sky) {
            this.sky = sky;
            return this;
        }

        /**
         * Sets the width of the band over which two levels of detail are dithered (default 1 m).
         *
         * @param lodTransition metres, in [0, 10]
         * @return this builder
         */
        public Builder lodTransition(double lodTransition) {
            this.lodTransition = lodTransition;
            return this;
        }

        /**
         * Sets which resource map tints the terrain (default none).
         *
         * @param terrainTint not null
         * @return this builder
         */
        public Builder terrainTint(Tint terrainTint) {
            this.terrainTint = terrainTint;
            return this;
        }

        /**
         * Sets whether the force-field overlay starts visible (default false).
         *
         * @param showField whether it starts visible
         * @return this builder
         */
        public Builder showField(boolean showField) {
            this.showField = showField;
            return this;
        }

        /**
         * Sets whether the wind-vector overlay starts visible (default false).
         *
         * @param showWind whether it starts visible
         * @return this builder
         */
        public Builder showWind(boolean showWind) {
            this.showWind = showWind;
            return this;
        }

        /**
         * Sets the sun, sky and atmosphere (default {@link Light#DEFAULT}).
         *
         * @param light not null
         * @return this builder
         */
        public Builder light(Light light) {
            this.light = light;
            return this;
        }

        /**
         * Sets the colour patches (default {@link Patches#DEFAULT}).
         *
         * @param patches not null
         * @return this builder
         */
        public Builder patches(Patches patches) {
            this.patches = patches;
            return this;
        }

        /**
         * Sets the samples per pixel (default {@link #DEFAULT_ANTIALIASING}).
         *
         * @param antialiasing 1, 2, 4 or 8
         * @return this builder
         */
        public Builder antialiasing(int antialiasing) {
            this.antialiasing = antialiasing;
            return this;
        }

        /**
         * Sets the ground cover (default {@link GroundCover#NONE}).
         *
         * @param groundCover not null
         * @return this builder
         */
        public Builder groundCover(GroundCover groundCover) {
            this.groundCover = groundCover;
            return this;
        }

        /**
         * The def. Allocates.
         *
         * @return a new def
         * @throws IllegalArgumentException when a value is null or out of range
         */
        public RenderDef build() {
            return new RenderDef(width, height, sky, lodTransition, terrainTint, showField, showWind, light, patches,
                    antialiasing, groundCover);
        }
    }
}
