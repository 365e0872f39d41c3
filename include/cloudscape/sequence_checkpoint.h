#pragma once
// The checkpoint of a temporal frame sequence (`render --frames`): the reconstruction's
// TemporalState after a frame, with a fingerprint of everything the sequence depends on, so that
// a rerun after a kill continues exactly where the checkpoint was taken instead of approximating
// the history. Stored as one EXR (written atomically, ZIP-compressed 32-bit float channels
// cloud.R/G/B/T, depth and weight at the history's size; the rest in string attributes), so it
// can be looked at with any EXR viewer.
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>
#include <cloudscape/temporal.h>

#include <string>

namespace cloudscape {

struct SequenceCheckpoint {
    std::string fingerprint; // sequenceFingerprint() of the run that wrote it
    TemporalState state;
};

// Throws cloudscape::Error for an empty state or a failed write (and leaves no file).
void writeSequenceCheckpoint(const std::string& path, const SequenceCheckpoint& checkpoint);
// Throws a one-line cloudscape::Error naming the path for a file that is not a checkpoint of
// this format version, or whose contents do not agree with each other.
SequenceCheckpoint readSequenceCheckpoint(const std::string& path);

// A hex fingerprint of what a sequence's frames depend on: every scene setting, the weather map
// and depth buffer contents, the camera path, the keyframes (Keyframes::fingerprintText, empty
// for none), frame rate and first frame (where the history starts), and the backend that
// renders (backends agree only to a tolerance).
std::string sequenceFingerprint(const Scene& base, const SceneResources& resources,
                                const std::string& cameraPath, const std::string& keyframes,
                                float fps, int firstFrame, const std::string& backend);

} // namespace cloudscape
