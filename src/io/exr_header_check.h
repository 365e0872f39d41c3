#pragma once
// The headers of an EXR file, checked before OpenEXR opens it (see exr_header_check.cpp).
#include <string>

namespace cloudscape::io {

// Throws cloudscape::Error naming the file unless every header attribute lies inside the file
// and holds exactly the bytes OpenEXR will read for its type.
void checkExrHeaders(const std::string& path);

} // namespace cloudscape::io
