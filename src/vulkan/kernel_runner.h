#pragma once
// Runs a small compute shader over storage buffers of vec4 (bindings 0..n-1) and returns their
// contents afterwards: the harness for the GPU unit kernels.
#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cloudscape::vulkan {

struct KernelRun {
    std::vector<std::vector<glm::vec4>> buffers;
    std::vector<std::string> validationMessages;
};

// spirv/bytes: the shader; groups: workgroups to dispatch along x.
KernelRun runKernel(const uint32_t* spirv, size_t bytes,
                    const std::vector<std::vector<glm::vec4>>& buffers, uint32_t groups,
                    bool validation);

} // namespace cloudscape::vulkan
