#pragma once
// How `render --frames` resumes exactly: the temporal state is checkpointed beside the frames
// every few frames (library: cloudscape/sequence_checkpoint.h), and a rerun restores the last
// checkpoint before its first missing frame and renders on from there, so every frame it writes
// has the bits an uninterrupted run would have written.
#include <cloudscape/persistent_renderer.h>

#include <string>

namespace cloudscape::cli {

// The checkpoint of a sequence whose output pattern is `pattern` and whose first frame is
// written to `firstFramePath`: `<pattern's file name>.checkpoint.exr` in that frame's directory.
std::string sequenceCheckpointPath(const std::string& pattern, const std::string& firstFramePath);

struct SequenceResume {
    int start = 0;            // the first frame to render
    int checkpointFrame = -1; // the frame of the checkpoint kept on disk (-1: none usable)
};

// Restores `renderer` from the checkpoint at `path` when it belongs to this sequence
// (`fingerprint`) and lies on the way to `firstMissing`; otherwise the sequence starts again at
// `first`. A checkpoint of another scene or setting is refused with a one-line
// cloudscape::Error rather than mixed with the frames on disk.
SequenceResume resumeSequence(Renderer& renderer, const std::string& path,
                              const std::string& fingerprint, int first, int firstMissing);

// Writes the renderer's state after its last frame atomically to `path`.
void writeCheckpoint(const Renderer& renderer, const std::string& path,
                     const std::string& fingerprint);

} // namespace cloudscape::cli
