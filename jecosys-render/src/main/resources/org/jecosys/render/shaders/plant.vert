#version 330 core
// Plants (paper section 4.1, 4.2.2): one instanced draw per species and level of detail. Each vertex
// names a slot (component instance of the plant), a pose-table point and side/normal coefficients.
// Per component, the CPU pass (ComponentStream) has already resolved the world position of the
// component's base (the plant's base plus its ground offset, or the animated tip of its parent), its
// bend azimuth as its cosine and sine, the pose-table texel of pose k, the blend weight toward k + 1
// and this level's dither window. The shader blends poses k and k + 1 of the point, rotates by the
// azimuth and adds the base: 2 + 6 texel fetches per vertex and no trigonometry. Line levels use
// plant_line.vert instead.

layout(location = 0) in vec4 aVertex;           // slot, point, a, b
layout(location = 1) in vec4 aColour;           // component colour (linear 0..1), fraction along it
layout(location = 2) in float aStride;          // texels between poses k and k + 1 of the slot (3 x points)

uniform mat4 uViewProj;
uniform vec3 uEye;
uniform vec3 uLightDir;                          // unit, toward the light
uniform samplerBuffer uPoses;                    // RGBA32F: 3 texels per point (position, side, normal)
uniform samplerBuffer uComponents;               // RGBA32F: 2 texels per drawn component
uniform int uSlotCount;
uniform int uComponentBase;
uniform vec3 uFogColour;
uniform float uFogStart;
uniform float uFogEnd;

out vec3 vColour;                                // lit and fogged per vertex
flat out vec2 vKeep;                             // keep fragments with lo <= bayer < hi

vec3 rotY(vec3 v, float c, float s) {
    // local +X goes to world (cos a, 0, sin a)
    return vec3(v.x * c - v.z * s, v.y, v.x * s + v.z * c);
}

void main() {
    int slot = int(aVertex.x);
    int point = int(aVertex.y);
    int ci = (uComponentBase + gl_InstanceID * uSlotCount + slot) * 2;
    vec4 c0 = texelFetch(uComponents, ci);       // base xyz, cos(azimuth)
    vec4 c1 = texelFetch(uComponents, ci + 1);   // texel of pose k, w, sin(azimuth), dither window
    int t = int(c1.x + 0.5) + point * 3;
    int u = t + int(aStride + 0.5);
    float w = c1.y;
    vec3 p = mix(texelFetch(uPoses, t).xyz, texelFetch(uPoses, u).xyz, w);
    vec3 side = mix(texelFetch(uPoses, t + 1).xyz, texelFetch(uPoses, u + 1).xyz, w);
    vec3 normal = mix(texelFetch(uPoses, t + 2).xyz, texelFetch(uPoses, u + 2).xyz, w);
    float ca = c0.w;
    float sa = c1.z;
    vec3 world = c0.xyz + rotY(p + aVertex.z * side + aVertex.w * normal, ca, sa);
    gl_Position = uViewProj * vec4(world, 1.0);

    // two-sided lighting: the face toward the viewer is lit by the sun, the back lets some through
    vec3 toEye = uEye - world;
    float distance = length(toEye);
    vec3 n = rotY(normal, ca, sa);
    float len = length(n);
    float lit = 0.65;
    if (len > 1e-9) {
        n /= len;
        n = dot(n, toEye) < 0.0 ? -n : n;
        float nl = dot(n, uLightDir);
        lit = max(nl, 0.0) + 0.35 * max(-nl, 0.0);
    }
    float along = aColour.w;
    vec3 colour = aColour.rgb * (0.50 + 0.55 * along);            // darker at the base: cheap occlusion
    colour = mix(colour, colour * vec3(1.10, 1.18, 0.80) + vec3(0.05, 0.06, 0.0), along * along); // sunlit tips
    float fog = clamp((distance - uFogStart) / max(uFogEnd - uFogStart, 1e-3), 0.0, 1.0);
    vColour = mix(colour * (0.45 + 0.75 * lit), uFogColour, fog * fog);

    int keep = int(c1.w + 0.5);
    vKeep = vec2(float(keep >> 8), float(keep & 255)) / 255.0;
}
