// Shared by plant.vert and plant_line.vert (#include): where a plant vertex goes and what colour it
// has. Placement (paper sections 4.1, 4.2.2): pose k and k + 1 of the point blended, rotated by the
// bend azimuth, added to the component's base. On top of the paper, for looks:
// - blades of plants kept where the frame thinned far plants out are drawn wider by 1 / the
//   kept share (at most 4 times; uThin), so a thinned meadow keeps most of its coverage;
// - thin parts stay at least uMinPixels wide: a ribbon narrower than that on screen is widened
//   across the view, and the share of the widened ribbon the real one covers goes out as coverage
//   (blended by it, on the samples the ribbon covers under multisampling);
// - stems face the camera (a ribbon turned about its own axis toward the eye), so they never vanish
//   edge-on;
// - flower parts (petals, heads) turn toward the viewer about their base by uFlowerTilt and are
//   scaled up to at least uHeadPixels across within 15 m, fading to their real size at 30 m (only
//   in the programs compiled with FLOWERS, for species that have flower parts: the others skip it);
// - colour varies per plant and per component: the resolve pass gives each component a hue turn, a
//   brightness factor and the dryness of its patch (plant_resolve.vert); here tips and dry patches
//   turn toward straw; light is sky ambient, sun diffuse, light through the blade when
//   back-lit (most through the thin tips), a specular term toward the tip, darkening toward the base
//   and low down inside the tuft, and a normal folded along the midrib, so it changes across a blade.

#include "plant_light.glsl"
#include "plant_far.glsl"

layout(location = 0) in vec4 aVertex;           // slot, point, a, b
layout(location = 1) in vec4 aColour;           // component colour (0..1), fraction along it
layout(location = 2) in float aStride;          // texels between poses k and k + 1 of the slot (3 x points)
layout(location = 3) in vec3 aShape;            // kind (0 blade, 1 stem, 2 petal, 3 fan head), reach (m),
                                                 // the component's texture layer (-1: none)
layout(location = 4) in vec4 aMesh;             // a vertex of a glTF mesh (w = 1; else 0): its offset along
                                                 // the skeleton's tangent (m), u and v on the image; aVertex
                                                 // then holds its fractional point and side and normal offsets (m)
layout(location = 5) in vec3 aMeshNormal;       // its normal in the skeleton's frame (side, tangent, normal)

uniform mat4 uViewProj;
uniform samplerBuffer uPoses;                    // RGBA32F: 3 texels per point (position, side, normal)
uniform samplerBuffer uComponents;               // RGBA32F: 3 texels per drawn component
uniform int uSlotCount;
uniform int uComponentBase;
uniform float uMinPixels;                        // least width of a thin part, pixels (0: off)
uniform float uHeadPixels;                       // least size of a flower part, pixels (0: off), already
                                                 // scaled to the picture's height (PlantRenderer)
uniform float uFlowerTilt;                       // turn of flower parts toward the viewer, radians
uniform float uFeather;                          // soft edge of blades and stems, pixels (0: off; targets
                                                 // without samples: their ribbons grow by it and fade over
                                                 // it at each side, so thin parts blend instead of stepping)


struct Placed {
    vec3 world;                                  // vertex position, world
    vec3 normal;                                 // surface normal, world, not normalised (0: none)
    vec3 toEye;                                  // eye - vertex
    float distance;                              // |toEye|
    float cover;                                 // share of the drawn width the real part covers
    vec2 edge;                                   // side (-1 to 1) and the drawn half width, pixels;
                                                 // the width negative for all but a blade (no midrib)
    float height;                                // height above the component's base, metres
};

vec3 rotY(vec3 v, float c, float s) {
    // local +X goes to world (cos a, 0, sin a)
    return vec3(v.x * c - v.z * s, v.y, v.x * s + v.z * c);
}

// rotation of v by angle t about the unit axis k (Rodrigues)
vec3 rotAxis(vec3 v, vec3 k, float t) {
    float c = cos(t);
    return v * c + cross(k, v) * sin(t) + k * dot(k, v) * (1.0 - c);
}

#ifdef TEXTURED
// Where the vertex lies on its component's image (plant.frag samples it): on a strip u runs across from
// the left edge (a = -1) to the right, v from the base to the tip; a fan's image is centred on its base,
// its rim on the image's edge
vec2 textureCoord() {
    if (aMesh.w > 0.5) {
        return aMesh.yz;
    }
    int kind = int(aShape.x + 0.5);
    return kind == 3 ? 0.5 + 0.5 * aVertex.zw : vec2(0.5 + 0.5 * aVertex.z, aColour.w);
}
#endif

// Places a vertex of a glTF mesh (aMesh.w = 1; ComponentMesh.place does the same on the CPU): between the
// pose-blended points p0 and p1 (with their half-width side vectors s0, s1) at the fraction f; the frame is
// the unit tangent along p1 - p0, the side blended (leaning to s0, which is never 0: only a tip has no
// width) and made normal to it, and their face normal; (ca, sa) the bend azimuth. Meshes keep their
// modelled size (no widening, no least size); flower parts turn toward the viewer like the petals.
Placed placeMesh(vec3 base, float ca, float sa, vec3 p0, vec3 s0, vec3 p1, vec3 s1, float f) {
    vec3 t = normalize(p1 - p0);
    vec3 s = s0 * (1.0 - f + 1e-3) + s1 * f;
    s = normalize(s - t * dot(s, t));
    vec3 n = cross(t, s);
    vec3 centre = base + rotY(mix(p0, p1, f), ca, sa);
    vec3 offset = rotY(aVertex.z * s + aMesh.x * t + aVertex.w * n, ca, sa);
    Placed r;
    r.normal = rotY(aMeshNormal.x * s + aMeshNormal.y * t + aMeshNormal.z * n, ca, sa);
#ifdef FLOWERS
    // a flower part (a head on its stalk) turns toward the viewer about the point it rides, as the petals do
    vec3 v = uEye - centre;
    float hl = length(v.xz);
    if (int(aShape.x + 0.5) >= 2 && hl > 1e-4 && uFlowerTilt != 0.0) {
        vec3 k = vec3(v.z, 0.0, -v.x) / hl;
        offset = rotAxis(offset, k, uFlowerTilt);
        r.normal = rotAxis(r.normal, k, uFlowerTilt);
    }
#endif
    r.world = centre + offset;
    r.cover = 1.0;
    r.edge = vec2(0.0, -1e4);
    r.toEye = uEye - r.world;
    r.distance = length(r.toEye);
    r.height = r.world.y - base.y;
    return r;
}

// Places the vertex: p, side, normal are the pose-blended point and its half-width vectors in the
// component's frame; (ca, sa) the bend azimuth; widen says whether thin parts are widened.
Placed place(vec3 base, float ca, float sa, vec3 p, vec3 side, vec3 normal, bool widen) {
    float a = aVertex.z;
    float b = aVertex.w;
    int kind = int(aShape.x + 0.5);
    vec3 pw = rotY(p, ca, sa);
    vec3 sw = rotY(side, ca, sa);
    vec3 nw = rotY(normal, ca, sa);
    vec3 centre = base + pw;
    vec3 toEye = uEye - centre;
    float d = max(length(toEye), 1e-4);
    vec3 v = toEye / d;
    if (kind < 2) {
        sw *= thinWiden(d);
    }
    float pix = uPixelScale.x + d * uPixelScale.y;
    Placed r;
    r.cover = 1.0;
    r.edge = vec2(0.0, -1e4);
#ifdef FLOWERS
    if (kind >= 2) {
        vec3 rel = pw + a * sw + b * nw;
        vec3 n = kind == 3 ? cross(sw, nw) : nw;  // a fan's disc faces along its axis
        float hl = length(v.xz);
        if (hl > 1e-4 && uFlowerTilt != 0.0) {
            vec3 k = vec3(v.z, 0.0, -v.x) / hl;  // turning +Y about k moves it toward the eye
            rel = rotAxis(rel, k, uFlowerTilt);
            n = rotAxis(n, k, uFlowerTilt);
        }
        // at least uHeadPixels across, fading back to the real size between 15 and 30 m, where a
        // flower is a speck in any case (and a head kept 8 pixels wide would crowd the horizon)
        float least = uHeadPixels * (1.0 - smoothstep(15.0, 30.0, d));
        rel *= max(1.0, 0.5 * least * pix / max(aShape.y, 1e-4));
        r.world = base + rel;
        r.normal = n;
    } else
#endif
    {
        float hw = length(sw);
        vec3 t = cross(sw, nw);                  // along the part
        vec3 across = cross(t, v);               // across the part, facing the eye
        float al = length(across);
        across = al > 1e-12 ? across / al : (hw > 0.0 ? sw / hw : vec3(1.0, 0.0, 0.0));
        if (dot(across, sw) < 0.0) {
            across = -across;
        }
        vec3 offset;
        float seen;                              // real half width as seen, metres
        if (kind == 1) {
            offset = across * hw;
            seen = hw;
            float tl = length(t);
            vec3 facing = tl > 1e-12 ? normalize(v - t * dot(v, t) / (tl * tl)) : v;
            r.normal = facing * 0.8 + across * (0.6 * a);
        } else {
            offset = sw;
            seen = max(length(sw - dot(sw, v) * v), 0.25 * hw);
            // a blade is folded along its midrib: each half's normal leans out to its own side, so the
            // light changes across the blade
            r.normal = hw > 0.0 ? nw + (0.55 * a * length(nw) / hw) * sw : nw;
        }
        vec3 world = centre + a * offset + b * nw;
        float drawn = seen;
        if (widen && uMinPixels > 0.0) {
            float least = 0.5 * uMinPixels * pix;
            world += a * max(least - seen, 0.0) * across;
            r.cover = clamp(seen / least, 0.0, 1.0);
            drawn = max(least, seen);
        }
        // the side and the drawn half width in pixels, negative for a stem (plant.frag: a blade's midrib)
        r.edge = vec2(a, (kind == 0 ? drawn : -drawn) / pix);
        if (widen && uFeather > 0.0) {
            // half the feather outward on each side: the fade then keeps the ribbon's weight
            float extra = 0.5 * uFeather * pix;
            world += a * extra * across;
            r.edge = vec2(a, (kind == 0 ? drawn + extra : -(drawn + extra)) / pix);
        }
        r.world = world;
    }
    r.toEye = uEye - r.world;
    r.distance = length(r.toEye);
    r.height = r.world.y - base.y;
    return r;
}

// The lit, fogged colour of a placed vertex; look is the component's record texel 2 (cos and sin of
// its hue turn, brightness factor, patch dryness); far drops the specular term; bend (0 to 1) and dir
// (unit, horizontal) are how far and which way the wind bends the component (its sheen).
vec3 shade(Placed v, vec4 look, bool far, float bend, vec2 dir) {
    int kind = int(aShape.x + 0.5);
    float along = aColour.w;
    return lit(albedo(aColour.rgb, look, kind, along), kind, along, v.height, v.normal, v.toEye, v.distance, far,
            bend, dir);
}
