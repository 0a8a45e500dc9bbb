#version 330 core
// Sky: a vertical gradient from the horizon colour (also the haze colour of plants and ground) to the
// zenith colour, brighter toward the sun, with a glow and the sun's disc; with uClouds above 0, fair-weather
// clouds on a plane high above, covering that share of the sky: four octaves of value noise, white and
// sunlit toward the sun, grey-blue undersides, thinning into the haze toward the horizon.
in vec4 vNear;
in vec4 vMid;
uniform vec3 uHorizon;
uniform vec3 uZenith;
uniform vec3 uSunDir;                            // unit vector toward the sun
uniform vec3 uSunColour;                         // sun colour times intensity
uniform float uClouds;                           // share of the sky the clouds cover, 0 for none
layout(location = 0) out vec4 fragColour;
// the resolve's detail mask (GlFramebuffer): 1 where thin geometry wants the wide filter, 0 elsewhere;
// written only into the library's own framebuffer (a host's other draw buffers are masked off)
layout(location = 1) out vec4 fragDetail;

float hash(vec2 i) {
    return fract(sin(dot(i, vec2(127.1, 311.7))) * 43758.5453);
}

float valueNoise(vec2 p) {
    vec2 i = floor(p);
    vec2 f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(hash(i), hash(i + vec2(1.0, 0.0)), u.x), mix(hash(i + vec2(0.0, 1.0)), hash(i + vec2(1.0, 1.0)), u.x),
            u.y);
}

// the clouds' cover (0 to 1) and how lit they are (0 underside to 1 sunlit), looking along dir
vec2 clouds(vec3 dir, float cosSun) {
    // the cloud plane seen along dir (up > 0), in units of a cloud's size
    vec2 p = dir.xz / (dir.y + 0.06) * 1.4 + vec2(13.7, -4.2);
    float n = 0.5 * valueNoise(p) + 0.25 * valueNoise(p * 2.03 + 5.1) + 0.125 * valueNoise(p * 4.01 + 9.7)
            + 0.0625 * valueNoise(p * 8.05 + 1.3);
    n /= 0.9375;
    // the noise sum clusters around 0.5 (s.d. about 0.12): this threshold leaves about uClouds of it above
    float edge = 0.75 - 0.5 * uClouds;
    float cover = smoothstep(edge - 0.05, edge + 0.08, n);
    cover *= smoothstep(0.02, 0.22, dir.y);      // thinning into the haze at the horizon
    // thicker cloud is darker beneath; toward the sun the edges glow
    float lit = clamp(1.0 - 1.6 * (n - edge), 0.0, 1.0) * 0.6 + 0.4 * cosSun;
    return vec2(cover, lit);
}

void main() {
    vec3 dir = normalize(vMid.xyz / vMid.w - vNear.xyz / vNear.w);
    float up = clamp(dir.y, 0.0, 1.0);
    // 1 - (1 - up)^2: quick toward the zenith colour as the square root was, but with a finite slope at the
    // horizon (the square root's infinite one made a bright seam a few rows above it)
    vec3 sky = mix(uHorizon, uZenith, up * (2.0 - up));
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
    if (uClouds > 0.0 && dir.y > 0.0) {
        vec2 cl = clouds(dir, c);
        vec3 under = mix(uZenith, uHorizon, 0.5) * 0.85 + vec3(0.12);
        vec3 top = vec3(0.97) + uSunColour * 0.12;
        colour = mix(colour, mix(under, top, cl.y), 0.92 * cl.x);
    }
    fragColour = vec4(min(colour, vec3(1.0)), 1.0);
    fragDetail = vec4(0.0);
}
