package org.jecosys.plant;

import java.util.List;
import org.jecosys.math.Rgb;

/**
 * One component type of a species: its skeleton shape (paper §4.1), its dynamic-constraint
 * parameters (paper §4.2, eq. 4-5; tau is the component's response time, a species property, not
 * the frame interval: see {@code org.jecosys.anim.SpringKinds}) and its drag. Immutable; any thread.
 *
 * @param id           unique within the species
 * @param type         leaf, petal, head or stalk
 * @param shape        how primitives are generated from the skeleton
 * @param count        how many of this component a plant has, in [1, 256]
 * @param attachTo     id of the component that carries these (petals on a stalk: see attachAt), or null for the ground
 * @param segments     skeleton segments (points = segments + 1), in [1, 32]
 * @param length       skeleton length, metres, in (0, 10]
 * @param baseWidth    width at the base, metres, in (0, 1]
 * @param tipWidth     width at the tip, metres, in [0, 1]
 * @param curvature    rest curvature before gravity, radians over the whole length, in [-pi, pi]
 * @param twist        twist around the skeleton over the whole length, radians, in [-2 pi, 2 pi]
 * @param tilt         angle of the base from vertical, radians, in [0, pi/2]
 * @param mass         mass, kilograms, in (0, 10]
 * @param stiffness    spring constant PC of eq. 4, N/m, in (0, 1e6]
 * @param responseTime response time tau of the spring, seconds, in [1e-3, 10]
 * @param dragArea     drag coefficient times area, m^2, in [0, 10]; force = 0.5 rho dragArea |u| u
 * @param colour       base colour
 * @param lodSegments  per species level of detail, how many segments this component uses there
 *                     (0 = not drawn at that level), each in [0, segments]
 * @param texture      an image (PNG with alpha) drawn on the component, as the scene writes its path
 *                     (relative to the scene's folder; read through the scene's image source), or null
 *                     for the plain colour; mapped along the skeleton for a strip (v from base to tip,
 *                     u across), radially for a fan; {@code colour} tints it (see {@link PlantTextures})
 * @param mesh         a glTF mesh drawn instead of the strip or fan where this component uses all its
 *                     segments (see {@link MeshDef}), or null; with a texture it needs texture coordinates
 * @param attachAt     where along the carrying component these sit, as a share of its skeleton, in (0, 1]:
 *                     1 its tip (petals, a flower head), less a point on the way up (leaves on a flower
 *                     stalk); the base snaps to the nearest skeleton point, at least the first above the
 *                     base ({@link #attachPoint}); 1 when attachTo is null
 */
public record ComponentDef(String id, ComponentType type, ComponentShape shape, int count, String attachTo,
                           int segments, double length, double baseWidth, double tipWidth, double curvature,
                           double twist, double tilt, double mass, double stiffness, double responseTime,
                           double dragArea, Rgb colour, List<Integer> lodSegments, String texture, MeshDef mesh,
                           double attachAt) {
    /**
     * Checks the components and copies {@code lodSegments}.
     *
     * @param id           unique within the species, not empty
     * @param type         leaf, petal, head or stalk, not null
     * @param shape        strip or fan, not null
     * @param count        components per plant, in [1, 256]
     * @param attachTo     id of the carrying component, or null for the ground (checked by the species)
     * @param segments     skeleton segments, in [1, 32]
     * @param length       skeleton length, metres, in [1e-6, 10]
     * @param baseWidth    width at the base, metres, in [1e-6, 1]
     * @param tipWidth     width at the tip, metres, in [0, 1]
     * @param curvature    rest curvature, radians, in [-pi, pi]
     * @param twist        twist over the length, radians, in [-2 pi, 2 pi]
     * @param tilt         base angle from vertical, radians, in [0, pi/2]
     * @param mass         kilograms, in [1e-9, 10]
     * @param stiffness    spring constant PC, N/m, in [1e-9, 1e6]
     * @param responseTime response time tau, seconds, in [1e-3, 10]
     * @param dragArea     drag coefficient times area, m^2, in [0, 10]
     * @param colour       base colour, not null
     * @param lodSegments  segments drawn per level of detail, each in [0, segments]
     * @param texture      the image drawn on it, as the scene writes its path, or null; not blank
     * @param mesh         the glTF mesh drawn for it, or null; with a texture, one with texture coordinates
     * @param attachAt     share of the carrier's skeleton where it sits, in [1e-3, 1]; 1 on the ground
     * @throws IllegalArgumentException when a component is null, empty or out of range
     */
    public ComponentDef {
        lodSegments = ComponentDefChecks.check(id, type, shape, count, attachTo, segments, length, baseWidth,
                tipWidth, curvature, twist, tilt, mass, stiffness, responseTime, dragArea, colour, lodSegments, texture,
                mesh, attachAt);
    }

    /**
     * A component at its carrier's tip ({@code attachAt} 1). Values as the canonical constructor's.
     *
     * @param id           unique within the species, not empty
     * @param type         leaf, petal, head or stalk
     * @param shape        strip or fan
     * @param count        components per plant, in [1, 256]
     * @param attachTo     id of the carrying component, or null for the ground
     * @param segments     skeleton segments, in [1, 32]
     * @param length       skeleton length, metres
     * @param baseWidth    width at the base, metres
     * @param tipWidth     width at the tip, metres
     * @param curvature    rest curvature, radians
     * @param twist        twist over the length, radians
     * @param tilt         base angle from vertical, radians
     * @param mass         kilograms
     * @param stiffness    spring constant PC, N/m
     * @param responseTime response time tau, seconds
     * @param dragArea     drag coefficient times area, m^2
     * @param colour       base colour
     * @param lodSegments  segments drawn per level of detail
     * @param texture      the image drawn on it, or null
     * @param mesh         the glTF mesh drawn for it, or null
     */
    public ComponentDef(String id, ComponentType type, ComponentShape shape, int count, String attachTo, int segments,
                        double length, double baseWidth, double tipWidth, double curvature, double twist, double tilt,
                        double mass, double stiffness, double responseTime, double dragArea, Rgb colour,
                        List<Integer> lodSegments, String texture, MeshDef mesh) {
        this(id, type, shape, count, attachTo, segments, length, baseWidth, tipWidth, curvature, twist, tilt, mass,
                stiffness, responseTime, dragArea, colour, lodSegments, texture, mesh, 1);
    }

    /**
     * {@return the skeleton point of the carrier ({@code carrierSegments} segments) this component's
     * base sits on: {@code round(attachAt carrierSegments)}, at least 1; the tip for attachAt 1}
     * Any thread; no allocation.
     *
     * @param carrierSegments the carrying component's skeleton segments, in [1, 32]
     */
    public int attachPoint(int carrierSegments) {
        return Math.max(1, Math.min(carrierSegments, (int) Math.round(attachAt * carrierSegments)));
    }

    /** Most components of one type per plant (the scene schema's range and the API's). */
    public static final int MAX_COUNT = 256;
    /** Most skeleton segments of a component. */
    public static final int MAX_SEGMENTS = 32;
    /** Shortest component, metres. */
    public static final double MIN_LENGTH = 1e-6;
    /** Longest component, metres. */
    public static final double MAX_LENGTH = 10;
    /** Narrowest base width, metres. */
    public static final double MIN_WIDTH = 1e-6;
    /** Widest base or tip, metres. */
    public static final double MAX_WIDTH = 1;
    /** Largest |rest curvature|, degrees (the API takes radians). */
    public static final double MAX_CURVATURE_DEGREES = 180;
    /** Largest |twist|, degrees. */
    public static final double MAX_TWIST_DEGREES = 360;
    /** Largest tilt of the base from vertical, degrees. */
    public static final double MAX_TILT_DEGREES = 90;
    /** Lightest component, kilograms. */
    public static final double MIN_MASS = 1e-9;
    /** Heaviest component, kilograms. */
    public static final double MAX_MASS = 10;
    /** Softest spring constant PC, N/m. */
    public static final double MIN_STIFFNESS = 1e-9;
    /** Stiffest spring constant PC, N/m. */
    public static final double MAX_STIFFNESS = 1e6;
    /** Shortest response time tau, seconds. */
    public static final double MIN_RESPONSE_TIME = 1e-3;
    /** Longest response time tau, seconds. */
    public static final double MAX_RESPONSE_TIME = 10;
    /** Smallest {@link #attachAt()}: a thousandth of the carrier's skeleton. */
    public static final double MIN_ATTACH_AT = 1e-3;
    /** Largest drag area, m^2. */
    public static final double MAX_DRAG_AREA = 10;

    /** Default {@link #shape()} (the scene schema's default too): a strip. */
    public static final ComponentShape DEFAULT_SHAPE = ComponentShape.STRIP;
    /** Default {@link #count()}: one per plant. */
    public static final int DEFAULT_COUNT = 1;
    /** Default {@link #tipWidth()}, metres: 0, a pointed tip. */
    public static final double DEFAULT_TIP_WIDTH = 0;
    /** Default {@link #curvature()}, radians: straight before gravity. */
    public static final double DEFAULT_CURVATURE = 0;
    /** Default {@link #twist()}, radians: none. */
    public static final double DEFAULT_TWIST = 0;
    /** Default {@link #tilt()}, radians: upright base. */
    public static final double DEFAULT_TILT = 0;
    /** Default {@link #responseTime()}, seconds. */
    public static final double DEFAULT_RESPONSE_TIME = 0.3;
    /** Default {@link #dragArea()}, m^2. */
    public static final double DEFAULT_DRAG_AREA = 0.001;
    /** Default {@link #colour()}: a mid green, #4a8a2a. */
    public static final Rgb DEFAULT_COLOUR = Rgb.parseHex("#4a8a2a");

    /**
     * A builder for a component type {@code id} of kind {@code type}, every other value at the scene
     * schema's default ({@code DEFAULT_*}; attachTo absent): what a {@code <component>} element with
     * only its required attributes loads as. Segments, length, baseWidth, mass, stiffness and
     * lodSegments have no default and must be set. Any thread; allocates.
     *
     * @param id   unique within the species, not empty
     * @param type leaf, petal, head or stalk
     * @return a new builder
     */
    public static Builder builder(String id, ComponentType type) {
        return new Builder(id, type);
    }

    /**
     * A builder holding every value of this def, to change a few. Any thread; allocates.
     *
     * @return a new builder
     */
    public Builder toBuilder() {
        Builder b = new Builder(id, type);
        b.shape = shape;
        b.count = count;
        b.attachTo = attachTo;
        b.segments = segments;
        b.length = length;
        b.baseWidth = baseWidth;
        b.tipWidth = tipWidth;
        b.curvature = curvature;
        b.twist = twist;
        b.tilt = tilt;
        b.mass = mass;
        b.stiffness = stiffness;
        b.responseTime = responseTime;
        b.dragArea = dragArea;
        b.colour = colour;
        b.lodSegments = lodSegments;
        b.texture = texture;
        b.mesh = mesh;
        b.attachAt = attachAt;
        return b;
    }

    /**
     * Fluent builder of a {@link ComponentDef} with the scene schema's defaults (see
     * {@link ComponentDef#builder}); values are checked by {@link #build()}. One thread; allocates.
     */
    public static final class Builder {
        private final String id;
        private final ComponentType type;
        private ComponentShape shape = DEFAULT_SHAPE;
        private int count = DEFAULT_COUNT;
        private String attachTo;
        private int segments = -1;
        private double length = Double.NaN;
        private double baseWidth = Double.NaN;
        private double tipWidth = DEFAULT_TIP_WIDTH;
        private double curvature = DEFAULT_CURVATURE;
        private double twist = DEFAULT_TWIST;
        private double tilt = DEFAULT_TILT;
        private double mass = Double.NaN;
        private double stiffness = Double.NaN;
        private double responseTime = DEFAULT_RESPONSE_TIME;
        private double dragArea = DEFAULT_DRAG_AREA;
        private Rgb colour = DEFAULT_COLOUR;
        private List<Integer> lodSegments;
        private String texture;
        private MeshDef mesh;
        private double attachAt = 1;

        private Builder(String id, ComponentType type) {
            this.id = id;
            this.type = type;
        }

        /**
         * Sets how primitives are generated from the skeleton.
         *
         * @param shape strip or fan
         * @return this builder
         */
        public Builder shape(ComponentShape shape) {
            this.shape = shape;
            return this;
        }

        /**
         * Sets how many of this component a plant has.
         *
         * @param count in [1, 256]
         * @return this builder
         */
        public Builder count(int count) {
            this.count = count;
            return this;
        }

        /**
         * Sets the component that carries these (at its tip unless {@link #attachAt} says otherwise).
         *
         * @param attachTo another component's id, or null for the ground
         * @return this builder
         */
        public Builder attachTo(String attachTo) {
            this.attachTo = attachTo;
            return this;
        }

        /**
         * Sets where along the carrier these sit (see {@link ComponentDef#attachAt()}).
         *
         * @param attachAt share of the carrier's skeleton, in [1e-3, 1]; 1 (the default) its tip
         * @return this builder
         */
        public Builder attachAt(double attachAt) {
            this.attachAt = attachAt;
            return this;
        }

        /**
         * Sets the skeleton segments (required).
         *
         * @param segments in [1, 32]
         * @return this builder
         */
        public Builder segments(int segments) {
            this.segments = segments;
            return this;
        }

        /**
         * Sets the skeleton length (required).
         *
         * @param length metres, in (0, 10]
         * @return this builder
         */
        public Builder length(double length) {
            this.length = length;
            return this;
        }

        /**
         * Sets the width at the base (required).
         *
         * @param baseWidth metres, in (0, 1]
         * @return this builder
         */
        public Builder baseWidth(double baseWidth) {
            this.baseWidth = baseWidth;
            return this;
        }

        /**
         * Sets the width at the tip.
         *
         * @param tipWidth metres, in [0, 1]
         * @return this builder
         */
        public Builder tipWidth(double tipWidth) {
            this.tipWidth = tipWidth;
            return this;
        }

        /**
         * Sets the rest curvature before gravity.
         *
         * @param curvature radians over the whole length, in [-pi, pi]
         * @return this builder
         */
        public Builder curvature(double curvature) {
            this.curvature = curvature;
            return this;
        }

        /**
         * Sets the twist around the skeleton.
         *
         * @param twist radians over the whole length, in [-2 pi, 2 pi]
         * @return this builder
         */
        public Builder twist(double twist) {
            this.twist = twist;
            return this;
        }

        /**
         * Sets the angle of the base from vertical.
         *
         * @param tilt radians, in [0, pi/2]
         * @return this builder
         */
        public Builder tilt(double tilt) {
            this.tilt = tilt;
            return this;
        }

        /**
         * Sets the mass (required).
         *
         * @param mass kilograms, in (0, 10]
         * @return this builder
         */
        public Builder mass(double mass) {
            this.mass = mass;
            return this;
        }

        /**
         * Sets the spring constant PC of eq. 4 (required).
         *
         * @param stiffness N/m, in (0, 1e6]
         * @return this builder
         */
        public Builder stiffness(double stiffness) {
            this.stiffness = stiffness;
            return this;
        }

        /**
         * Sets the response time tau of the spring.
         *
         * @param responseTime seconds, in [1e-3, 10]
         * @return this builder
         */
        public Builder responseTime(double responseTime) {
            this.responseTime = responseTime;
            return this;
        }

        /**
         * Sets the drag coefficient times area.
         *
         * @param dragArea m^2, in [0, 10]
         * @return this builder
         */
        public Builder dragArea(double dragArea) {
            this.dragArea = dragArea;
            return this;
        }

        /**
         * Sets the base colour.
         *
         * @param colour not null
         * @return this builder
         */
        public Builder colour(Rgb colour) {
            this.colour = colour;
            return this;
        }

        /**
         * Sets the segments used per level of detail of the species (required).
         *
         * @param lodSegments one value per level, each in [0, segments]; 0 = not drawn there
         * @return this builder
         */
        public Builder lodSegments(List<Integer> lodSegments) {
            this.lodSegments = lodSegments;
            return this;
        }

        /**
         * Sets the segments used per level of detail of the species (required).
         *
         * @param lodSegments one value per level, each in [0, segments]; 0 = not drawn there
         * @return this builder
         */
        public Builder lodSegments(int... lodSegments) {
            this.lodSegments = ComponentDefChecks.list(lodSegments);
            return this;
        }

        /**
         * Sets the image drawn on the component.
         *
         * @param texture its path as a scene writes it (read through the scene's image source), or null
         *                for the plain colour
         * @return this builder
         */
        public Builder texture(String texture) {
            this.texture = texture;
            return this;
        }

        /**
         * Sets the glTF mesh drawn for the component where it uses all its segments.
         *
         * @param mesh the mesh, or null for the strip or fan
         * @return this builder
         */
        public Builder mesh(MeshDef mesh) {
            this.mesh = mesh;
            return this;
        }

        /**
         * The def. Allocates.
         *
         * @return a new def
         * @throws IllegalStateException    when a value without default (segments, length, baseWidth,
         *                                  mass, stiffness, lodSegments) was not set
         * @throws IllegalArgumentException when a value is out of range (see {@link ComponentDef})
         */
        public ComponentDef build() {
            ComponentDefChecks.requireSet(id, segments, length, baseWidth, mass, stiffness, lodSegments);
            return new ComponentDef(id, type, shape, count, attachTo, segments, length, baseWidth, tipWidth,
                    curvature, twist, tilt, mass, stiffness, responseTime, dragArea, colour, lodSegments, texture, mesh,
                    attachAt);
        }
    }
}
