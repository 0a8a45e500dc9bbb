#version 330 core
// Terrain: lit by the sun and the sky's ambient light, coloured by the healthy/dry patches, hazed
// toward the horizon colour with distance exactly as the plants are (aerial perspective). Lighting
// and patches per vertex (mesh cells are small against their scales, and llvmpipe shades far more
// fragments than vertices); the fragment shader lays the ground cover over the soil, applies the
// contact occlusion under the plants and the haze, per fragment so that the horizon skirt's huge
// triangles fade like the rest.
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColour;
uniform mat4 uViewProj;
uniform vec3 uEye;
uniform vec3 uLightDir;                          // unit vector toward the sun
uniform vec3 uSunColour;                         // sun colour times intensity
uniform vec3 uAmbient;                           // sky light on an upward-facing surface
uniform vec4 uOcclusionMap;                      // minX, minZ, 1 / (texelX * width), 1 / (texelZ * height)
uniform vec2 uOcclusionHalf;                     // half a texel in texture coordinates
out vec3 vSoil;                                  // the soil's colour (tint, dry patches)
out vec3 vLight;                                 // the sky's light falling on the ground, before contact occlusion
out vec3 vSunLight;                              // the sun's, before contact occlusion and the plants' shadows
out vec3 vWorld;                                 // position, metres: the haze is worked out per fragment
out vec3 vUvDry;                                 // occlusion-map coordinates, dryness of the patch
#ifdef COVER_SKIN
uniform float uLift;                             // share of the way to the eye the cover skin is drawn nearer
#endif

#include "patches.glsl"

void main() {
#ifdef COVER_SKIN
    // the ground cover's skin over a host's own ground (CoverSkin): moved toward the eye along its view
    // ray, so it covers the same pixels but a little nearer (a depth bias growing with distance, as the
    // depth buffer's steps do): it wins over a host's ground at the same height, not over what stands on it
    gl_Position = uViewProj * vec4(mix(aPos, uEye, uLift), 1.0);
#else
    gl_Position = uViewProj * vec4(aPos, 1.0);
#endif
    // the horizon skirt reaches far beyond any far plane: drawn just inside it instead of clipped, so
    // the ground meets the sky at the horizon (the sky is drawn where the depth is still 1)
    gl_Position.z = min(gl_Position.z, 0.999999 * gl_Position.w);
    vec3 n = normalize(aNormal);
    vec3 albedo = aColour;
    float dry = 0.0;
    if (uPatch.z > 0.5) {
        // dry patches: paler, yellower soil
        dry = uPatch.y * patchLevel(aPos.xz);
        albedo = mix(albedo, vec3(0.46, 0.40, 0.27), 0.6 * dry);
    }
    float diffuse = max(dot(n, uLightDir), 0.0);
    vLight = uAmbient * (0.5 + 0.5 * n.y);
    vSunLight = uSunColour * diffuse;
    vSoil = albedo;
    vWorld = aPos;
    vUvDry = vec3((aPos.xz - uOcclusionMap.xy) * uOcclusionMap.zw + uOcclusionHalf, dry);
}
