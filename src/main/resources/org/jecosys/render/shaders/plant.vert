#version 330 core
// Plants (paper section 4.1, 4.2.2): one instanced draw per species and level of detail. Each vertex
// names a slot (component instance of the plant), a pose-table point and side/normal coefficients.
// The vertex shader blends poses k and k+1 of the component's pose table, rotates the result by the
// component's bend azimuth and places it at the component's base: the plant's base plus the slot's
// ground offset, or the animated tip of the parent component it is attached to.

layout(location = 0) in vec4 aVertex;           // slot, point, a, b

uniform mat4 uViewProj;
uniform vec3 uEye;
uniform vec3 uLightDir;                          // unit, toward the light
uniform usamplerBuffer uInstances;               // RGBA32UI: x, y, z (float bits), azimuth | kind << 16
uniform samplerBuffer uPoses;                    // RGBA32F: 3 texels per point (position, side, normal)
uniform isamplerBuffer uSlots;                   // RGBA32I: 2 texels per (variant, slot)
uniform samplerBuffer uBend;                     // RG32F: (pose coordinate, bend azimuth) per component
uniform int uInstanceBase;
uniform int uSlotBase;
uniform int uSlotCount;
uniform int uComponentBase;
uniform int uLevel;
uniform int uLevels;
uniform float uEdges[8];
uniform float uBand;

out vec3 vColour;
out float vDistance;
flat out vec2 vKeep;                             // keep fragments with handOver <= bayer < received

const float TWO_PI = 6.28318530718;

vec3 rotY(vec3 v, float a) {
    // local +X goes to world (cos a, 0, sin a)
    float c = cos(a);
    float s = sin(a);
    return vec3(v.x * c - v.z * s, v.y, v.x * s + v.z * c);
}

ivec4 slotA(int variant, int slot) {
    return texelFetch(uSlots, uSlotBase + (variant * uSlotCount + slot) * 2);
}

ivec4 slotB(int variant, int slot) {
    return texelFetch(uSlots, uSlotBase + (variant * uSlotCount + slot) * 2 + 1);
}

vec2 bendOf(int slot) {
    return texelFetch(uBend, uComponentBase + gl_InstanceID * uSlotCount + slot).xy;
}

// texel index of (pose k, point) and the blend weight toward k + 1
int poseTexel(ivec4 a, float coord, int point, out float w) {
    int poses = a.w;
    int points = a.y;
    float c = clamp(coord, 0.0, float(poses - 1));
    int k = min(int(c), poses - 2);
    w = c - float(k);
    return a.x + (k * points + point) * 3;
}

vec3 blended(int t, int rowStride, float w, int field) {
    return mix(texelFetch(uPoses, t + field).xyz, texelFetch(uPoses, t + rowStride + field).xyz, w);
}

float fadeAt(float d, int edge) {
    float e = uEdges[edge];
    if (uBand <= 0.0) {
        return d >= e ? 1.0 : 0.0;
    }
    return clamp((d - (e - uBand)) / uBand, 0.0, 1.0);
}

void main() {
    uvec4 inst = texelFetch(uInstances, uInstanceBase + gl_InstanceID);
    vec3 plant = vec3(uintBitsToFloat(inst.x), uintBitsToFloat(inst.y), uintBitsToFloat(inst.z));
    float restAzimuth = float(inst.w & 0xFFFFu) * (TWO_PI / 65536.0);
    int variant = int((inst.w >> 16u) & 0x3Fu);

    int slot = int(aVertex.x);
    int point = int(aVertex.y);

    // base of the component: walk up the attachment chain (at most 4 deep)
    vec3 base = vec3(0.0);
    int s = slot;
    for (int i = 0; i < 4; i++) {
        ivec4 a = slotA(variant, s);
        int parent = a.z;
        if (parent < 0) {
            ivec4 b = slotB(variant, s);
            base += rotY(vec3(intBitsToFloat(b.x), 0.0, intBitsToFloat(b.y)), restAzimuth);
            break;
        }
        ivec4 pa = slotA(variant, parent);
        vec2 pb = bendOf(parent);
        float pw;
        int pt = poseTexel(pa, pb.x, pa.y - 1, pw);
        base += rotY(blended(pt, pa.y * 3, pw, 0), pb.y);
        s = parent;
    }

    ivec4 a = slotA(variant, slot);
    vec2 bend = bendOf(slot);
    float w;
    int t = poseTexel(a, bend.x, point, w);
    int row = a.y * 3;
    vec3 p = blended(t, row, w, 0);
    vec3 side = blended(t, row, w, 1);
    vec3 normal = blended(t, row, w, 2);
    vec3 local = p + aVertex.z * side + aVertex.w * normal;
    vec3 world = plant + base + rotY(local, bend.y);
    gl_Position = uViewProj * vec4(world, 1.0);

    // two-sided Lambert with a sky ambient term
    vec3 n = rotY(normal, bend.y);
    float len = length(n);
    float diffuse = len > 1e-9 ? abs(dot(n / len, uLightDir)) : 0.6;
    int rgba = slotB(variant, slot).z;
    vec3 colour = vec3(float(rgba & 255), float((rgba >> 8) & 255), float((rgba >> 16) & 255)) / 255.0;
    float height = clamp(p.y / 0.4, 0.0, 1.0);   // darker near the ground: cheap occlusion
    vColour = colour * (0.42 + 0.58 * diffuse) * (0.75 + 0.25 * height);

    // level-of-detail dither: which share of this plant's pixels this level keeps
    float d = distance(uEye, plant);
    vDistance = distance(uEye, world);
    float handOver = uLevel < uLevels - 1 ? fadeAt(d, uLevel) : 0.0;
    float received = uLevel > 0 ? fadeAt(d, uLevel - 1) : 1.0;
    vKeep = vec2(handOver, uLevel > 0 && d >= uEdges[uLevel - 1] ? 1.0 : received);
}
