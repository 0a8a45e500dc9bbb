#version 330 core
// The per-component pass of plant rendering, on the GPU (paper sections 4.1, 4.2.2): one vertex per
// drawn component, no rasterisation; its two outputs are captured by transform feedback into the
// component records that plant.vert and plant_line.vert read (2 RGBA32F texels per drawn component,
// in draw-list order). Inputs: the instance records of this frame (first component of the drawn
// plant and its level's dither window), the compact animated state of every component (8 bytes:
// pose coordinate and bend azimuth, two floats, as the simulation's workers wrote them), and static
// per-component data uploaded once (the base of a root component, the pose texel of its table, its
// parent, stride, tip and pose count). The base of an attached component is its parent's animated
// tip, which follows its own parent, up to 4 deep.
//
// Record: r0 = (base xyz, cos azimuth), r1 = (texel of pose k point 0, blend weight w toward
// pose k + 1, sin azimuth, packed word: dither window in bits 0-15, an 8-bit hash of the plant in
// bits 16-23, for its colour variation; exact in a float).

uniform isamplerBuffer uInstances;               // RG32I: first component, dither window
uniform samplerBuffer uDynamic;                  // RG32F: pose coordinate, bend azimuth (radians)
uniform samplerBuffer uStatic;                   // RGBA32F: root base xyz (world), texel of pose 0
uniform isamplerBuffer uLinks;                   // RGBA32I: parent component or -1, texels per pose, tip, poses
uniform samplerBuffer uPoses;                    // RGBA32F: 3 texels per point (position, side, normal)
uniform int uInstanceBase;                       // first instance record of this draw list
uniform int uSlots;                              // components per plant of this species

out vec4 vRecord0;
out vec4 vRecord1;

struct Pose {
    int texel;                                   // texel of pose k, point 0
    float w;                                     // weight toward pose k + 1
    float c;                                     // cos azimuth
    float s;                                     // sin azimuth
};

Pose pose(int component, ivec4 link, float texel0) {
    vec2 d = texelFetch(uDynamic, component).xy;
    float coord = clamp(d.x, 0.0, float(link.w - 1));
    int k = min(int(coord), link.w - 2);
    Pose p;
    p.texel = int(texel0 + 0.5) + k * link.y;
    p.w = coord - float(k);
    p.c = cos(d.y);
    p.s = sin(d.y);
    return p;
}

void main() {
    int i = gl_VertexID / uSlots;
    int slot = gl_VertexID - i * uSlots;
    ivec2 instance = texelFetch(uInstances, uInstanceBase + i).xy;
    int component = instance.x + slot;
    vec4 st = texelFetch(uStatic, component);
    ivec4 link = texelFetch(uLinks, component);
    Pose own = pose(component, link, st.w);
    vec3 base = vec3(0.0);
    for (int depth = 0; depth < 4; depth++) {
        if (link.x < 0) {
            base += st.xyz;
            break;
        }
        int parent = link.x;
        st = texelFetch(uStatic, parent);
        link = texelFetch(uLinks, parent);
        Pose pp = pose(parent, link, st.w);
        int t = pp.texel + link.z;
        vec3 tip = mix(texelFetch(uPoses, t).xyz, texelFetch(uPoses, t + link.y).xyz, pp.w);
        base += vec3(tip.x * pp.c - tip.z * pp.s, tip.y, tip.x * pp.s + tip.z * pp.c);
    }
    vRecord0 = vec4(base, own.c);
    // the plant's first component names it: its 8-bit hash rides above the 16-bit dither window
    uint h = uint(instance.x) * 0x9e3779b9u;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    int plantHash = int((h >> 24) & 255u);
    vRecord1 = vec4(float(own.texel), own.w, own.s, float((instance.y & 65535) | (plantHash << 16)));
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
