// The resolve filter of a multisampled framebuffer, shared by its plain and temporal passes. The
// samples of each pixel have been averaged into image (a box filter one pixel wide); resolveFiltered
// widens that where thin geometry was drawn. weights mixes the plain average (x), a tent of one
// pixel's radius (y: the 3x3 binomial 1 2 1, four bilinear taps at the pixel's corners) and a wider
// binomial (z: 5x5, 1 4 6 4 1 per axis, nine bilinear taps), so that blades moving by a fraction of a
// pixel change the image smoothly; detail (the detail mask the plants write, averaged like the image)
// says where: the wider filters apply at and around plant pixels, while everywhere else (terrain
// against sky) the box keeps edges sharp.
vec4 resolveFiltered(sampler2D image, sampler2D detailMask, vec2 uv, vec2 texel, vec3 weights) {
    // detail at this pixel or within the wide filter's reach: the nine taps of the wide filter
    float detail = 0.0;
    for (int j = -1; j <= 1; j++) {
        for (int i = -1; i <= 1; i++) {
            detail = max(detail, texture(detailMask, uv + texel * vec2(1.5 * float(i), 1.5 * float(j))).r);
        }
    }
    vec3 w = mix(vec3(1.0, 0.0, 0.0), weights, clamp(4.0 * detail, 0.0, 1.0));
    vec4 box = texture(image, uv);
    vec4 colour = w.x * box;
    if (w.y > 0.0) {
        vec4 tent = 0.25 * (texture(image, uv + texel * vec2(-0.5, -0.5)) + texture(image, uv + texel * vec2(0.5, -0.5))
                + texture(image, uv + texel * vec2(-0.5, 0.5)) + texture(image, uv + texel * vec2(0.5, 0.5)));
        colour += w.y * tent;
    }
    if (w.z > 0.0) {
        // per axis: 6/16 at 0, 5/16 at +-1.2 pixels (the pairs 4, 1 of the binomial in one bilinear tap)
        vec4 wide = vec4(0.0);
        for (int j = -1; j <= 1; j++) {
            for (int i = -1; i <= 1; i++) {
                float k = (i == 0 ? 0.375 : 0.3125) * (j == 0 ? 0.375 : 0.3125);
                wide += k * texture(image, uv + texel * vec2(1.2 * float(i), 1.2 * float(j)));
            }
        }
        colour += w.z * wide;
    }
    return colour;
}
