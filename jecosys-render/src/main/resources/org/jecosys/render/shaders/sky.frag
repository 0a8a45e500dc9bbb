#version 330 core
// Sky: a vertical gradient from the horizon colour (also the haze colour of plants and ground) to the
// zenith colour, brighter toward the sun, with a glow and the sun's disc.
in vec4 vNear;
in vec4 vMid;
uniform vec3 uHorizon;
uniform vec3 uZenith;
uniform vec3 uSunDir;                            // unit vector toward the sun
uniform vec3 uSunColour;                         // sun colour times intensity
layout(location = 0) out vec4 fragColour;
// the resolve's detail mask (GlFramebuffer): 1 where thin geometry wants the wide filter, 0 elsewhere;
// written only into the library's own framebuffer (a host's other draw buffers are masked off)
layout(location = 1) out vec4 fragDetail;

void main() {
    vec3 dir = normalize(vMid.xyz / vMid.w - vNear.xyz / vNear.w);
    float up = clamp(dir.y, 0.0, 1.0);
    vec3 sky = mix(uHorizon, uZenith, sqrt(up));
    float c = max(dot(dir, uSunDir), 0.0);
    // broad forward scattering, stronger near the horizon, and a tight glow around the disc; powers by
    // squaring (pow is exp and log in a software rasteriser)
    float c2 = c * c;
    float c4 = c2 * c2;
    float c16 = c4 * c4;
    c16 *= c16;
    float c64 = c16 * c16;
    float glow = 0.22 * c4 * (1.0 - 0.5 * up) + 0.45 * c64;
    float disc = smoothstep(0.99985, 0.99993, c);  // about 0.7 degrees across
    vec3 colour = sky + uSunColour * (glow + 2.0 * disc);
    fragColour = vec4(min(colour, vec3(1.0)), 1.0);
    fragDetail = vec4(0.0);
}
