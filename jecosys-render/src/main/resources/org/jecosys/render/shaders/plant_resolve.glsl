// The per-component pass of plant rendering, on the GPU (paper sections 4.1, 4.2.2), shared by its two
// forms (#include): plant_resolve.vert (OpenGL 3.3: one vertex per drawn component, no rasterisation,
// the record captured by transform feedback) and plant_resolve.comp (OpenGL 4.3: one invocation per
// drawn component, the record stored into a shader storage buffer). Either way the records are what
// plant.vert and plant_line.vert read (3 RGBA32F texels per drawn component, in draw-list order).
// Inputs: the instance records of this frame (first component of the drawn plant and its level's
// dither window), the compact animated state of every component (8 bytes: its deviation D, world X
// and Z, two floats, as the simulation's workers wrote them), and static per-component data uploaded
// once (the base of a root component, the pose texel of its table, its parent, stride, tip and pose
// count; its bend geometry: rest lean, length and pose scale). D becomes pose coordinate and azimuth
// here as the CPU's BendGeometry makes them (see "Bend" in AnimationState), to float rounding. The base of an attached component is the animated point of its parent it sits on (the tip unless
// its attachAt says otherwise), which follows its
// own parent, up to 4 deep; the variant compiled without ATTACHED, for species whose components all
// stand on the ground (most grasses), leaves that walk out.
//
// Record: r0 = (base xyz, cos azimuth), r1 = (texel of pose k point 0, blend weight w toward
// pose k + 1, sin azimuth, dither window + 0.99 x the bend: pose coordinate / last pose), r2 = (cos and sin of the component's hue turn, its
// brightness factor, the dryness of the plant's patch): the colour variation, worked out per component
// on the CPU when the look changes (ComponentLooks, texture uLooks), not per frame; for a
// line (far) level r2 is instead what all the component's vertices share (plant_far.glsl): its
// colour lit once at its middle point, its thinning widening, 1 / its distance, a pixel's size there.

uniform isamplerBuffer uInstances;               // RG32I: first component, dither window
uniform samplerBuffer uDynamic;                  // RG32F: deviation D (X, Z), metres
uniform samplerBuffer uBend;                     // RGBA32F: rest lean L (X, Z), metres; length, metres; pose scale
uniform samplerBuffer uStatic;                   // RGBA32F: root base xyz (world), texel of pose 0
uniform isamplerBuffer uLinks;                   // RGBA32I: parent component or -1, texels per pose, the texel
                                                 // offset of the parent's point it sits on (its tip on the ground), poses
uniform samplerBuffer uPoses;                    // RGBA32F: 3 texels per point (position, side, normal)
#ifdef LIST_TABLE
// the compute form resolves many lists in one dispatch: each invocation sets these from its list
// (initialised here too: the compiler cannot see that main sets them before any use, and warns)
int uInstanceBase = 0;
int uSlots = 1;
int uLines = 0;
int uSlotBase = 0;
#else
uniform int uInstanceBase;                       // first instance record of this draw list
uniform int uSlots;                              // components per plant of this species
uniform int uLines;                              // 1: this list is a line level (texel 2 = far record)
uniform int uSlotBase;                           // first slot look of this list's species
#endif

uniform usamplerBuffer uLooks;                   // RG32UI per component: its baked colour variation
uniform samplerBuffer uSlotLooks;                // RGBA32F per species slot: colour, vertex kind

#include "plant_light.glsl"
#include "plant_far.glsl"

struct Pose {
    int texel;                                   // texel of pose k, point 0
    float w;                                     // weight toward pose k + 1
    float c;                                     // cos azimuth
    float s;                                     // sin azimuth
    float bend;                                  // pose coordinate over the last pose: 0 rest, 1 most bent
};

// atan(x) for x in [-1, 1]: the CPU's polynomial (Trig.atanUnit, Abramowitz and Stegun 4.4.49), so the
// pose coordinate does not depend on the driver's asin, whose error reaches 1e-4 rad on some (llvmpipe)
float atanUnit(float x) {
    float z = x * x;
    return x * (1.0 + z * (-0.3333314528 + z * (0.1999355085 + z * (-0.1420889944 + z * (0.1065626393
            + z * (-0.0752896400 + z * (0.0429096138 + z * (-0.0161657367 + z * 0.0028662257))))))));
}

Pose pose(int component, ivec4 link, float texel0) {
    vec2 d = texelFetch(uDynamic, component).xy;
    vec4 g = texelFetch(uBend, component);
    // the tip moves from L to T = L + D: the azimuth is T's direction ((0, 1) for T = 0, as on the
    // CPU); the extra tip offset |T| - |L| times (|T| + |L|) is num = 2 L.D + |D|^2 (no cancellation),
    // and the extra bend asin(e / length) = atan2(num, sqrt(dd^2 - num^2)) with dd = (|T| + |L|) length,
    // as pi/4 + atan((num - den) / (num + den)); the pose scale maps it to the pose coordinate
    vec2 t = g.xy + d;
    float r = length(t);
    float num = max(0.0, 2.0 * dot(g.xy, d) + dot(d, d));
    float dd = (r + length(g.xy)) * g.z;
    float den = sqrt(max(0.0, (dd - num) * (dd + num)));
    float bend = 0.7853981634 + atanUnit((num - den) / max(num + den, 1e-30));
    float coord = clamp(bend * g.w, 0.0, float(link.w - 1));
    int k = min(int(coord), link.w - 2);
    Pose p;
    p.texel = int(texel0 + 0.5) + k * link.y;
    p.w = coord - float(k);
    p.c = r > 0.0 ? t.x / r : 0.0;
    p.s = r > 0.0 ? t.y / r : 1.0;
    p.bend = coord / float(max(link.w - 1, 1));
    return p;
}

// The record of the index-th component drawn by this list (plant index / slots, slot index % slots).
void resolveComponent(int index, out vec4 record0, out vec4 record1, out vec4 record2) {
    int i = index / uSlots;
    int slot = index - i * uSlots;
    ivec2 instance = texelFetch(uInstances, uInstanceBase + i).xy;
    int component = instance.x + slot;
    vec4 st = texelFetch(uStatic, component);
    ivec4 link = texelFetch(uLinks, component);
    Pose own = pose(component, link, st.w);
    int stride = link.y;                         // texels per pose of this component (3 x points)
#ifdef ATTACHED
    vec3 base = vec3(0.0);
    for (int depth = 0; depth < 4; depth++) {
        if (link.x < 0) {
            base += st.xyz;
            break;
        }
        int parent = link.x;
        int at = link.z;                         // the parent's point this one sits on, x 3 texels
        st = texelFetch(uStatic, parent);
        link = texelFetch(uLinks, parent);
        Pose pp = pose(parent, link, st.w);
        int t = pp.texel + at;
        vec3 tip = mix(texelFetch(uPoses, t).xyz, texelFetch(uPoses, t + link.y).xyz, pp.w);
        base += vec3(tip.x * pp.c - tip.z * pp.s, tip.y, tip.x * pp.s + tip.z * pp.c);
    }
#else
    vec3 base = st.xyz;
#endif
    record0 = vec4(base, own.c);
    // the dither window is a whole number below 2^16: the fraction carries the bend (1/256 steps)
    record1 = vec4(float(own.texel), own.w, own.s, float(instance.y) + 0.99 * clamp(own.bend, 0.0, 1.0));
    // colour variation, baked per component on the CPU when the look changes (ComponentLooks): the
    // hue turn (radians, float bits), brightness factor x 32768 and patch dryness x 65535
    uvec2 baked = texelFetch(uLooks, component).xy;
    float hue = uintBitsToFloat(baked.x);
    vec4 look = vec4(cos(hue), sin(hue), float(baked.y & 0xFFFFu) / 32768.0, float(baked.y >> 16) / 65535.0);
    if (uLines == 0) {
        record2 = look;
    } else {
        // a line level: light the component once, at its middle point; its distance and the
        // widening and pixel size there, once for all its vertices
        vec4 slotLook = texelFetch(uSlotLooks, uSlotBase + slot);  // colour, kind
        int kind = int(slotLook.w + 0.5);
        int points = stride / 3;
        int mid = points / 2;
        float along = float(mid) / float(max(points - 1, 1));
        int t = own.texel + mid * 3;
        vec3 p = mix(texelFetch(uPoses, t).xyz, texelFetch(uPoses, t + stride).xyz, own.w);
        vec3 side = mix(texelFetch(uPoses, t + 1).xyz, texelFetch(uPoses, t + 1 + stride).xyz, own.w);
        vec3 normal = mix(texelFetch(uPoses, t + 2).xyz, texelFetch(uPoses, t + 2 + stride).xyz, own.w);
        vec3 n = kind == 3 ? cross(side, normal) : normal;
        vec3 world = base + vec3(p.x * own.c - p.z * own.s, p.y, p.x * own.s + p.z * own.c);
        n = vec3(n.x * own.c - n.z * own.s, n.y, n.x * own.s + n.z * own.c);
        vec3 toEye = uEye - world;
        vec3 c = albedo(slotLook.rgb, look, kind, along);
        // seen from afar a tuft shows its outer leaves: no shade by height (plant_line.vert shades by along)
        record2 = farRecord(lit(c, kind, along, 1.0, n, toEye, length(toEye), true, own.bend, vec2(own.c, own.s)),
                max(length(uEye - base), 1e-4));
    }
}
