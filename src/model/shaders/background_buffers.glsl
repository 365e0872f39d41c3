// Shader plumbing (GLSL only): the background a temporal renderer keeps per output pixel, as
// storage texel buffers (texel_rows.glsl says why): its light (pixel.glsl.h's BackgroundLight,
// three rows), filled by the PASS_FILL_BACKGROUND pipeline when the renderer's background
// changed, and the background under this frame's clouds (BackgroundTexel, two rows), made from
// that light by the PASS_SHADE_BACKGROUND pipeline when the light or the clouds changed and read
// by the composite. Define BACKGROUND_BINDING and BACKGROUND_SEEN_BINDING first.
layout(binding = BACKGROUND_BINDING, rgba32f) uniform imageBuffer backgroundTexels;
layout(binding = BACKGROUND_SEEN_BINDING, rgba32f) uniform imageBuffer seenTexels;

BackgroundLight loadBackground(int i) {
    BackgroundLight b;
    b.base = imageLoad(backgroundTexels, BACKGROUND_LIGHT_ROWS * i);
    b.beam = imageLoad(backgroundTexels, BACKGROUND_LIGHT_ROWS * i + 1);
    b.diffuse = imageLoad(backgroundTexels, BACKGROUND_LIGHT_ROWS * i + 2);
    return b;
}

void storeBackground(int i, BackgroundLight b) {
    imageStore(backgroundTexels, BACKGROUND_LIGHT_ROWS * i, b.base);
    imageStore(backgroundTexels, BACKGROUND_LIGHT_ROWS * i + 1, b.beam);
    imageStore(backgroundTexels, BACKGROUND_LIGHT_ROWS * i + 2, b.diffuse);
}

BackgroundTexel loadSeen(int i) {
    BackgroundTexel t;
    t.beyond = imageLoad(seenTexels, BACKGROUND_TEXEL_ROWS * i);
    t.seen = imageLoad(seenTexels, BACKGROUND_TEXEL_ROWS * i + 1);
    return t;
}

void storeSeen(int i, BackgroundTexel t) {
    imageStore(seenTexels, BACKGROUND_TEXEL_ROWS * i, t.beyond);
    imageStore(seenTexels, BACKGROUND_TEXEL_ROWS * i + 1, t.seen);
}
