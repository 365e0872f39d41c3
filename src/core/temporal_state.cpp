// The one check of a TemporalState before either backend takes it as its history.
#include <cloudscape/error.h>

#include "core/model_params.h"
#include "core/temporal_impl.h"
#include "model/interface.glsl.h"
#include "model/sample_gather.glsl.h"

#include <algorithm>
#include <cstring>

namespace cloudscape {

void checkTemporalState(const TemporalState& state) {
    if (state.empty())
        throw Error("temporal state: no frame to continue from");
    if (state.width <= 0 || state.height <= 0 || state.width > 65536 || state.height > 65536)
        throw Error("temporal state: invalid history size " + std::to_string(state.width) + "x" +
                    std::to_string(state.height));
    const size_t pixels = static_cast<size_t>(state.width) * state.height;
    if (state.cloud.size() != pixels * 4 || state.depth.size() != pixels ||
        state.weight.size() != pixels || (!state.flash.empty() && state.flash.size() != pixels))
        throw Error("temporal state: the history arrays do not match its size " +
                    std::to_string(state.width) + "x" + std::to_string(state.height));
    if (state.frameParams.size() != sizeof(model::FrameParams))
        throw Error("temporal state: frame parameters of " +
                    std::to_string(state.frameParams.size()) + " bytes, expected " +
                    std::to_string(sizeof(model::FrameParams)));
    const size_t frameBytes = sizeof(model::FrameParams);
    const size_t ringFrames = state.gatherFrames.size() / frameBytes;
    // The ring's records, then (with a ring) the entering ring's (sample_gather.glsl.h).
    const glm::ivec2 size(state.width, state.height);
    const size_t ringRecords =
        ringFrames * static_cast<size_t>(model::gatherSlotBlocks(size)) +
        (ringFrames > 0 ? static_cast<size_t>(model::enteringRingRecords(size)) : 0);
    if (state.gatherFrames.size() % frameBytes != 0 ||
        ringFrames > static_cast<size_t>(model::GATHER_MAX_FRAMES) ||
        state.gatherRing.size() != ringRecords * (sizeof(model::CloudTexel) / sizeof(float)))
        throw Error("temporal state: the ring of gathered marches does not match its " +
                    std::to_string(ringFrames) + " frames at " + std::to_string(state.width) + "x" +
                    std::to_string(state.height));
    model::FrameParams frame;
    std::memcpy(&frame, state.frameParams.data(), sizeof frame);
    if (ringFrames != 0 && ringFrames != static_cast<size_t>(std::max(frame.gatherFrames, 0)))
        throw Error("temporal state: a ring of " + std::to_string(ringFrames) +
                    " gathered frames, its frame parameters say " +
                    std::to_string(frame.gatherFrames));
    if (frame.width != state.width || frame.height != state.height)
        throw Error("temporal state: the frame parameters are for " + std::to_string(frame.width) +
                    "x" + std::to_string(frame.height) + ", the history is " +
                    std::to_string(state.width) + "x" + std::to_string(state.height));
}

TemporalDebugImage temporalDebugImageOf(const float* codes, int width, int height) {
    static_assert(static_cast<int>(TemporalSource::Marched) == model::TEMPORAL_SOURCE_MARCHED &&
                  static_cast<int>(TemporalSource::Reprojected) ==
                      model::TEMPORAL_SOURCE_REPROJECTED &&
                  static_cast<int>(TemporalSource::Fallback) == model::TEMPORAL_SOURCE_FALLBACK);
    TemporalDebugImage image;
    image.width = width;
    image.height = height;
    const size_t pixels = static_cast<size_t>(width) * height;
    image.source.resize(pixels);
    image.samples.resize(pixels);
    for (size_t i = 0; i < pixels; ++i) {
        image.source[i] = static_cast<TemporalSource>(model::texelDebugSource(codes[i]));
        image.samples[i] = model::texelDebugSamples(codes[i]);
    }
    return image;
}

} // namespace cloudscape
