// Harness: the temporal sequence checkpoint reader (`render --frames` resuming,
// readSequenceCheckpoint): an EXR whose cloud.R/G/B/T, depth and weight planes are the history
// and whose string attributes hold the format, fingerprint, frame, time bits and frame
// parameters; then checkTemporalState, the check either backend makes before taking it as its
// history. A checkpoint that loads is consistent: a frame index of at least 0, four history
// values and one depth and weight per pixel.
#include <cloudscape/sequence_checkpoint.h>

#include "core/temporal_impl.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string path = cloudscape::fuzz::scratchFile(".checkpoint.exr");
    cloudscape::fuzz::writeScratch(path, data, size);
    cloudscape::fuzz::runExpectingOnlyCloudscapeErrors([&] {
        const cloudscape::SequenceCheckpoint checkpoint = cloudscape::readSequenceCheckpoint(path);
        const cloudscape::TemporalState& s = checkpoint.state;
        const size_t pixels = static_cast<size_t>(s.width) * static_cast<size_t>(s.height);
        if (s.frameIndex < 0 || s.cloud.size() != pixels * 4 || s.depth.size() != pixels ||
            s.weight.size() != pixels) {
            std::fprintf(
                stderr, "fuzz: checkpoint of frame %d, %dx%d pixels holds %zu/%zu/%zu values\n",
                s.frameIndex, s.width, s.height, s.cloud.size(), s.depth.size(), s.weight.size());
            std::abort();
        }
        cloudscape::checkTemporalState(s);
    });
    return 0;
}
