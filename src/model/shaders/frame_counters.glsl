// Shader plumbing (GLSL only): summing a pass's statistics into the FrameCounters record of
// interface.glsl.h without a per-pixel readback. Each workgroup sums in shared memory, then one
// invocation adds the sums to the buffer; 64-bit totals are (low, high) word pairs with the
// carry taken from the value atomicAdd returns. Include after declaring
//   layout(std430, binding = ...) buffer Counters { FrameCounters counters; };
// Every invocation of the workgroup must call countSamples / countSource and flushCounters,
// including those outside the image (with zeros), because flushCounters holds a barrier.
shared uint groupDensity;
shared uint groupLight;
shared uint groupCloud;
shared uint groupSkips;
shared uint groupSources[3];
shared uint groupEntering;

void beginCounters() {
    if (gl_LocalInvocationIndex == 0u) {
        groupDensity = 0u;
        groupLight = 0u;
        groupCloud = 0u;
        groupSkips = 0u;
        groupSources[0] = 0u;
        groupSources[1] = 0u;
        groupSources[2] = 0u;
        groupEntering = 0u;
    }
    barrier();
}

// A march's density samples (of which `cloud` in cloud), light samples and empty-space skips.
void countSamples(uint density, uint light, uint cloud, uint skips) {
    if (density != 0u) {
        atomicAdd(groupDensity, density);
    }
    if (light != 0u) {
        atomicAdd(groupLight, light);
    }
    if (cloud != 0u) {
        atomicAdd(groupCloud, cloud);
    }
    if (skips != 0u) {
        atomicAdd(groupSkips, skips);
    }
}

// Adds a workgroup's sum to a 64-bit total kept as (low, high) words (a macro: atomicAdd needs
// the buffer's member itself, which a function's parameter would copy).
#define ADD_WIDE(low, high, sum)                                                                   \
    if ((sum) != 0u) {                                                                             \
        uint before = atomicAdd(low, sum);                                                         \
        if (before + (sum) < before) {                                                             \
            atomicAdd(high, 1u);                                                                   \
        }                                                                                          \
    }

// The block march's entering marches (sample_gather.glsl.h's enteringMarchCount).
void countEntering(uint marches) {
    if (marches != 0u) {
        atomicAdd(groupEntering, marches);
    }
}

void countSource(int source) {
    atomicAdd(groupSources[source], 1u);
}

void flushCounters() {
    barrier();
    if (gl_LocalInvocationIndex != 0u) {
        return;
    }
    ADD_WIDE(counters.densitySamplesLow, counters.densitySamplesHigh, groupDensity)
    ADD_WIDE(counters.lightSamplesLow, counters.lightSamplesHigh, groupLight)
    ADD_WIDE(counters.cloudSamplesLow, counters.cloudSamplesHigh, groupCloud)
    ADD_WIDE(counters.emptySkipsLow, counters.emptySkipsHigh, groupSkips)
    atomicAdd(counters.marched, groupSources[TEMPORAL_SOURCE_MARCHED]);
    atomicAdd(counters.reprojected, groupSources[TEMPORAL_SOURCE_REPROJECTED]);
    atomicAdd(counters.fallback, groupSources[TEMPORAL_SOURCE_FALLBACK]);
    if (groupEntering != 0u) {
        atomicAdd(counters.entering, groupEntering);
    }
}
