#pragma once
// Recording and running one command buffer to completion, the way every pass of the backend is
// submitted. Plumbing only.
#include "vulkan/vulkan_context.h"

#include <functional>

namespace cloudscape::vulkan {

// Records `record` into a fresh one-time command buffer, submits it and waits for it; throws
// cloudscape::Error if the wait fails.
void submitAndWait(const Context& ctx, const std::function<void(vk::CommandBuffer)>& record);

// A barrier making compute-shader writes visible to the host's reads of mapped memory.
void shaderWritesToHost(vk::CommandBuffer cmd);
// A barrier between two compute dispatches, the second reading what the first wrote.
void shaderWritesToShader(vk::CommandBuffer cmd);

} // namespace cloudscape::vulkan
