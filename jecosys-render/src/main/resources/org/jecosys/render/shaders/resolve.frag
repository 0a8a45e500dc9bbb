#version 330 core
// The second half of a multisampled framebuffer's resolve: the samples of each pixel have been
// averaged (a box filter one pixel wide); this widens the filter where thin geometry was drawn.
// uWeights mixes the plain average (x), a tent of one pixel's radius (y: the 3x3 binomial 1 2 1,
// four bilinear taps at the pixel's corners) and a wider binomial (z: 5x5, 1 4 6 4 1 per axis, nine
// bilinear taps), so that blades moving by a fraction of a pixel change the image smoothly; uDetail
// (the detail mask the plants write, averaged like the image) says where: the wide filter applies
// at and around plant pixels, while everywhere else (terrain against sky) the box keeps edges sharp.
uniform sampler2D uImage;
uniform sampler2D uDetail;
uniform vec2 uTexel;                             // 1 / size
uniform vec3 uWeights;                           // box, tent, wide; sum 1
layout(location = 0) out vec4 fragColour;

void main() {
    vec2 uv = gl_FragCoord.xy * uTexel;
    // detail at this pixel or within the wide filter's reach: the nine taps of the wide filter
    float detail = 0.0;
    for (int j = -1; j <= 1; j++) {
        for (int i = -1; i <= 1; i++) {
            detail = max(detail, texture(uDetail, uv + uTexel * vec2(1.5 * float(i), 1.5 * float(j))).r);
        }
    }
    vec3 weights = mix(vec3(1.0, 0.0, 0.0), uWeights, clamp(4.0 * detail, 0.0, 1.0));
    vec4 box = texture(uImage, uv);
    vec4 colour = weights.x * box;
    if (weights.y > 0.0) {
        vec4 tent = 0.25 * (texture(uImage, uv + uTexel * vec2(-0.5, -0.5)) + texture(uImage, uv + uTexel * vec2(0.5, -0.5))
                + texture(uImage, uv + uTexel * vec2(-0.5, 0.5)) + texture(uImage, uv + uTexel * vec2(0.5, 0.5)));
        colour += weights.y * tent;
    }
    if (weights.z > 0.0) {
        // per axis: 6/16 at 0, 5/16 at +-1.2 pixels (the pairs 4, 1 of the binomial in one bilinear tap)
        vec4 wide = vec4(0.0);
        for (int j = -1; j <= 1; j++) {
            for (int i = -1; i <= 1; i++) {
                float w = (i == 0 ? 0.375 : 0.3125) * (j == 0 ? 0.375 : 0.3125);
                wide += w * texture(uImage, uv + uTexel * vec2(1.2 * float(i), 1.2 * float(j)));
            }
        }
        colour += weights.z * wide;
    }
    fragColour = colour;
}
