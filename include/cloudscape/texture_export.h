#pragma once
// Export of the generated textures for use in other engines. For a texture `name` in an existing
// directory this writes, as one set (all four files or, on any failure, none; atomic_files.h):
//   name.png   level 0 as an 8-bit slice atlas (slices left to right, top to bottom)
//   name.raw   level 0 as UNORM8, `channels` bytes per texel, x fastest, then y, then z
//   name.exr   level 0 as a float atlas with the same layout as the PNG
//   name.json  a sidecar with the size, format, layout and atlas grid
#include <cloudscape/atomic_files.h>
#include <cloudscape/texture.h>

#include <string>
#include <vector>

namespace cloudscape {

void exportTexture3D(const Texture3D& texture, int channels, const std::string& directory,
                     const std::string& name);
void exportTexture2D(const Texture2D& texture, int channels, const std::string& directory,
                     const std::string& name);

// The same, written into `files`: nothing lands until files.commit(), so several textures can be
// exported as one set.
void exportTexture3D(const Texture3D& texture, int channels, const std::string& directory,
                     const std::string& name, AtomicFileSet& files);
void exportTexture2D(const Texture2D& texture, int channels, const std::string& directory,
                     const std::string& name, AtomicFileSet& files);

// The four paths an export of `name` into `directory` writes.
std::vector<std::string> textureExportFiles(const std::string& directory, const std::string& name);

} // namespace cloudscape
