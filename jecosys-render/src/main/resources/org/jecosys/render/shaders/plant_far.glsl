// What the resolve pass works out once per component of a line (far) level for all its vertices
// (#include; plant_resolve.glsl writes it, plant_line.vert reads it): record texel 2 holds the
// component's lit colour and the widening its blades get where the frame thins far plants out, each
// in 12 bits, two to a float (whole numbers below 2^24, which a float holds exactly), then
// 1 / the distance of its base from the eye and the height of a pixel there (metres).
uniform vec2 uPixelScale;                        // a pixel's height, metres: x + distance * y
uniform vec3 uThin;                              // the frame's distance thinning: start, end (m), least share

// How much wider a kept far blade is drawn to make up for the plants the frame's decision thinned
// out at distance d: 1 / the kept share, so the kept ones carry about the same ink, at most 4 times
// (wider, far blades turn into blobs); 1 without thinning.
float thinWiden(float d) {
    if (uThin.z >= 1.0) {
        return 1.0;
    }
    float kept = 1.0 - (1.0 - uThin.z) * smoothstep(uThin.x, uThin.y, d);
    return min(1.0 / max(kept, 0.05), 4.0);
}

// two values in [0, 1] as one float: 12 bits each (signed integers: a software rasteriser converts
// them between float and integer in one instruction, unsigned ones in several)
float pack12(float lo, float hi) {
    int a = int(clamp(lo, 0.0, 1.0) * 4095.0 + 0.5);
    int b = int(clamp(hi, 0.0, 1.0) * 4095.0 + 0.5);
    return float(a | (b << 12));
}

// record texel 2 of a line level's component: lit colour (0..1), base at distance d (metres)
vec4 farRecord(vec3 colour, float d) {
    return vec4(pack12(colour.r, colour.g), pack12(colour.b, (thinWiden(d) - 1.0) / 3.0), 1.0 / d,
            uPixelScale.x + d * uPixelScale.y);
}

// the lit colour of a far record
vec3 farColour(vec4 r2) {
    int a = int(r2.x);
    int b = int(r2.y);
    return vec3(float(a & 4095), float(a >> 12), float(b & 4095)) * (1.0 / 4095.0);
}

// the thinning widening of a far record (1 to 4)
float farWiden(vec4 r2) {
    return 1.0 + float(int(r2.y) >> 12) * (3.0 / 4095.0);
}
