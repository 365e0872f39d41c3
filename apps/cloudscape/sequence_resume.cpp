// Resuming a frame sequence from its checkpoint: see sequence_resume.h.
#include "sequence_resume.h"

#include <cloudscape/error.h>
#include <cloudscape/sequence_checkpoint.h>

#include <filesystem>

namespace cloudscape::cli {
namespace fs = std::filesystem;

std::string sequenceCheckpointPath(const std::string& pattern, const std::string& firstFramePath) {
    const fs::path frame(firstFramePath);
    const fs::path directory = frame.has_parent_path() ? frame.parent_path() : fs::path(".");
    return (directory / (fs::path(pattern).filename().string() + ".checkpoint.exr")).string();
}

SequenceResume resumeSequence(Renderer& renderer, const std::string& path,
                              const std::string& fingerprint, int first, int firstMissing) {
    SequenceResume resume;
    resume.start = first;
    if (!fs::exists(path))
        return resume;
    SequenceCheckpoint checkpoint;
    try {
        checkpoint = readSequenceCheckpoint(path);
    } catch (const Error& e) {
        throw Error(std::string(e.what()) + "; use --force to render the sequence again");
    }
    if (checkpoint.fingerprint != fingerprint)
        throw Error(path + ": checkpoint of a different scene, camera path, keyframes, frame "
                           "rate, first frame or backend; its frames would not match (use --force "
                           "to render the sequence again)");
    resume.checkpointFrame = checkpoint.state.frameIndex;
    // A checkpoint past the first missing frame (one was deleted) cannot rebuild that frame's
    // history: start again from the first frame, which is exact too.
    if (checkpoint.state.frameIndex < first || checkpoint.state.frameIndex >= firstMissing)
        return resume;
    renderer.restoreState(checkpoint.state);
    resume.start = checkpoint.state.frameIndex + 1;
    return resume;
}

void writeCheckpoint(const Renderer& renderer, const std::string& path,
                     const std::string& fingerprint) {
    writeSequenceCheckpoint(path, {fingerprint, renderer.saveState()});
}

} // namespace cloudscape::cli
