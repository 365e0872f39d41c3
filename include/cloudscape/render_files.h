#pragma once
// Where a render's layers go in a file, in the library rather than in the command-line tool, so
// every caller writes the same layout.
#include <cloudscape/pathtrace.h>
#include <cloudscape/renderer.h>

#include <string>

namespace cloudscape {

// Linear EXR of a RenderResult with every layer (Readback::All): the composite R, G, B, A, and
// the premultiplied cloud layer cloud.R/G/B, cloud.A = 1 - transmittance (for compositors),
// cloud.T = transmittance, cloud.Z = distance to the first cloud in metres (+inf where none).
// Written atomically; throws cloudscape::Error naming the path.
void writeRenderExr(const std::string& path, const RenderResult& result);

// The path tracer's running estimate: R, G, B (the mean), A = 1, and the header attributes
// cloudscape.samples (samples per pixel) and cloudscape.scene (the fingerprint), so a render
// can be resumed. Written atomically.
void writePathTraceCheckpoint(const std::string& path, const PathTraceImage& image,
                              const std::string& fingerprint);
// Reads a checkpoint to continue it; throws cloudscape::Error naming the path if it is not a
// checkpoint or was rendered from another scene (fingerprint).
PathTraceImage readPathTraceCheckpoint(const std::string& path, const std::string& fingerprint);

} // namespace cloudscape
