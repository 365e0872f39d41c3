// Shader plumbing (GLSL only): the background pass's list of pixels that need the ground's
// two-sample cloud shadow (interface.glsl.h's ground fallback list; pixel.glsl.h's
// backgroundTexelFrom says which). llvmpipe runs both sides of a branch under a lane mask, so the
// fallback inside the shade pass was paid by every pixel; the pass built without
// FEATURE_GROUND_FALLBACK lists the few that need it and an indirect dispatch over the list
// (PASS_GROUND_FALLBACK) shades those again with it. Include after background_buffers.glsl and
// the declarations of `frame` and `cloud`, with GROUND_FALLBACK_BINDING defined; its workgroup
// holds GROUND_FALLBACK_GROUP invocations.
layout(std430, binding = GROUND_FALLBACK_BINDING) buffer GroundFallbackList {
    uint fallbackGroups[3]; // the indirect dispatch's group counts (x grows as pixels are listed)
    uint fallbackCount;
    uint fallbackPixels[];
};

// Adds a pixel (its index in the image) to the list, and a workgroup to the dispatch for every
// GROUND_FALLBACK_GROUP pixels.
void listGroundFallback(int pixelIndex) {
    uint slot = atomicAdd(fallbackCount, 1u);
    fallbackPixels[slot] = uint(pixelIndex);
    if (slot % uint(GROUND_FALLBACK_GROUP) == 0u) {
        atomicAdd(fallbackGroups[0], 1u);
    }
}

// The index of the listed pixel this invocation of the dispatch over the list shades; -1 past
// the list's end. By its workgroup's id, which holds only because the host records the indirect
// dispatch after a plain vkCmdDispatch: lavapipe (Mesa 22) starts an indirect dispatch's ids at
// the base of the last vkCmdDispatchBase (docs/PERFORMANCE.md, "The march in two dispatches").
int listedGroundFallback() {
    uint slot = gl_WorkGroupID.x * uint(GROUND_FALLBACK_GROUP) + gl_LocalInvocationIndex;
    return slot < fallbackCount ? int(fallbackPixels[slot]) : -1;
}

// A background dispatch's pixel (index i) from its light: this frame's background, and the pixel
// listed where this pipeline left the fallback out and the pixel needs it.
void shadeBackground(BackgroundLight light, ivec2 pixel, int i) {
    bool groundFallback = false;
    storeSeen(i, backgroundTexelFrom(light, pixel, frame, cloud, groundFallback));
    if (!featureCompiled(FEATURE_GROUND_FALLBACK) && groundFallback) {
        listGroundFallback(i);
    }
}

// The dispatch over the list: the listed pixels' background again, with the fallback.
void shadeListedGroundFallback() {
    int listed = listedGroundFallback();
    if (listed >= 0) {
        ivec2 pixel = ivec2(listed % frame.width, listed / frame.width);
        storeSeen(listed, backgroundTexelFrom(loadBackground(listed), pixel, frame, cloud));
    }
}
