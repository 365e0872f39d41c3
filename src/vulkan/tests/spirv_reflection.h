#pragma once
// A minimal SPIR-V reader for the interface test: the descriptor bindings, push-constant block and
// struct layouts a compiled shader declares, read from its words (the same words the backend
// loads). Enough of the SPIR-V 1.5 binary format for glslc's output; no dependency.
#include "model/interface.glsl.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace cloudscape::testing {

class SpirvModule {
public:
    struct Binding {
        uint32_t set = 0;
        uint32_t binding = 0;
        model::DescriptorKind kind = model::DescriptorKind::UniformBuffer;
        uint32_t blockType = 0; // the block struct (buffers) or the sampled image type
    };

    SpirvModule(const uint32_t* words, size_t count) {
        if (count < 5 || words[0] != 0x07230203u)
            throw std::runtime_error("not a SPIR-V module");
        for (size_t i = 5; i < count;) {
            const uint32_t length = words[i] >> 16, op = words[i] & 0xffffu;
            if (length == 0 || i + length > count)
                throw std::runtime_error("truncated SPIR-V instruction");
            read(op, std::vector<uint32_t>(words + i + 1, words + i + length));
            i += length;
        }
    }

    // Every resource variable with a descriptor binding.
    std::vector<Binding> bindings() const {
        std::vector<Binding> out;
        for (const auto& [id, variable] : variables_) {
            const auto binding = decoration(id, kBinding);
            if (!binding)
                continue;
            Binding b;
            b.binding = *binding;
            b.set = decoration(id, kDescriptorSet).value_or(0);
            const uint32_t type = pointee(variable.pointerType);
            b.blockType = type;
            if (variable.storage == kStorageBuffer ||
                (variable.storage == kUniform && decoration(type, kBufferBlock)))
                b.kind = model::DescriptorKind::StorageBuffer;
            else if (variable.storage == kUniform)
                b.kind = model::DescriptorKind::UniformBuffer;
            else if (variable.storage == kUniformConstant && sampledImages_.count(type))
                b.kind = isBufferImage(sampledImages_.at(type))
                             ? model::DescriptorKind::UniformTexelBuffer
                             : model::DescriptorKind::CombinedImageSampler;
            else if (variable.storage == kUniformConstant && isBufferImage(type))
                b.kind = model::DescriptorKind::StorageTexelBuffer;
            else
                throw std::runtime_error("binding of an unsupported kind");
            out.push_back(b);
        }
        return out;
    }

    // The image format a storage image declares (SPIR-V's ImageFormat: 1 Rgba32f, 3 R32f; 0 for
    // none, as a texel buffer read through a sampler has); type: a binding's blockType.
    uint32_t imageFormat(uint32_t type) const {
        const auto sampled = sampledImages_.find(type);
        const auto image = images_.find(sampled != sampledImages_.end() ? sampled->second : type);
        return image == images_.end() ? 0u : image->second.second;
    }
    static constexpr uint32_t kImageFormatRgba32f = 1;

    std::optional<Binding> binding(uint32_t set, uint32_t number) const {
        for (const Binding& b : bindings())
            if (b.set == set && b.binding == number)
                return b;
        return std::nullopt;
    }

    // The push-constant block's struct type (0 if the shader has none).
    uint32_t pushConstantBlock() const {
        for (const auto& [id, variable] : variables_)
            if (variable.storage == kPushConstant)
                return pointee(variable.pointerType);
        return 0;
    }

    // Member types and offsets of a struct type.
    const std::vector<uint32_t>& members(uint32_t structType) const {
        return structs_.at(structType);
    }
    std::vector<uint32_t> memberOffsets(uint32_t structType) const {
        std::vector<uint32_t> out;
        for (size_t m = 0; m < members(structType).size(); ++m)
            out.push_back(memberDecoration(structType, static_cast<uint32_t>(m), kOffset).value());
        return out;
    }
    // Bytes a value of the type occupies (a struct: up to the end of its last member).
    uint32_t sizeOf(uint32_t type) const {
        if (scalars_.count(type))
            return scalars_.at(type);
        if (vectors_.count(type))
            return sizeOf(vectors_.at(type).first) * vectors_.at(type).second;
        if (arrays_.count(type)) // stride times length (CloudParams.cloudTops)
            return decoration(type, kArrayStride).value() * constants_.at(arrays_.at(type).second);
        if (structs_.count(type)) {
            uint32_t end = 0;
            const std::vector<uint32_t> offsets = memberOffsets(type);
            for (size_t m = 0; m < offsets.size(); ++m)
                end = std::max(end, offsets[m] + sizeOf(structs_.at(type)[m]));
            return end;
        }
        throw std::runtime_error("size of an unsupported type");
    }
    bool isStruct(uint32_t type) const { return structs_.count(type) != 0; }
    // The element type and stride of a runtime array type, or nullopt if type is not one.
    std::optional<std::pair<uint32_t, uint32_t>> runtimeArray(uint32_t type) const {
        const auto it = runtimeArrays_.find(type);
        if (it == runtimeArrays_.end())
            return std::nullopt;
        return std::make_pair(it->second, decoration(type, kArrayStride).value());
    }

    // The SpecId decorations of the module's specialisation constants.
    std::vector<uint32_t> specIds() const {
        std::vector<uint32_t> out;
        for (const auto& [key, value] : decorations_)
            if (key.second == kSpecId)
                out.push_back(value);
        return out;
    }

    // Elements of the largest array in any function-local variable (a struct's arrays counted
    // through its members): the copies a driver may have to keep in scratch memory.
    uint32_t largestLocalArray() const {
        uint32_t largest = 0;
        for (const auto& [id, variable] : variables_)
            if (variable.storage == kFunction)
                largest = std::max(largest, largestArrayIn(pointee(variable.pointerType)));
        return largest;
    }

private:
    static constexpr uint32_t kFunction = 7;
    uint32_t largestArrayIn(uint32_t type) const {
        if (arrays_.count(type)) {
            const auto& [element, length] = arrays_.at(type);
            return std::max(constants_.at(length), largestArrayIn(element));
        }
        uint32_t largest = 0;
        if (structs_.count(type))
            for (uint32_t member : structs_.at(type))
                largest = std::max(largest, largestArrayIn(member));
        return largest;
    }
    static constexpr uint32_t kSpecId = 1, kBlock = 2, kBufferBlock = 3, kArrayStride = 6,
                              kBinding = 33, kDescriptorSet = 34, kOffset = 35;
    static constexpr uint32_t kUniformConstant = 0, kUniform = 2, kPushConstant = 9,
                              kStorageBuffer = 12;

    struct Variable {
        uint32_t pointerType = 0;
        uint32_t storage = 0;
    };

    void read(uint32_t op, const std::vector<uint32_t>& a) {
        switch (op) {
        case 21: // OpTypeInt
        case 22: // OpTypeFloat
            scalars_[a[0]] = a[1] / 8;
            break;
        case 23: // OpTypeVector
            vectors_[a[0]] = {a[1], a[2]};
            break;
        case 25: // OpTypeImage: result, sampled type, dim, depth, arrayed, MS, sampled, format
            images_[a[0]] = {a[2], a[7]};
            break;
        case 27: // OpTypeSampledImage
            sampledImages_[a[0]] = a[1];
            break;
        case 28: // OpTypeArray: element type, the id of its length
            arrays_[a[0]] = {a[1], a[2]};
            break;
        case 43: // OpConstant (32-bit): type, id, value
            if (a.size() == 3)
                constants_[a[1]] = a[2];
            break;
        case 29: // OpTypeRuntimeArray
            runtimeArrays_[a[0]] = a[1];
            break;
        case 30: // OpTypeStruct
            structs_[a[0]] = std::vector<uint32_t>(a.begin() + 1, a.end());
            break;
        case 32: // OpTypePointer
            pointers_[a[0]] = a[2];
            break;
        case 59: // OpVariable
            variables_[a[1]] = {a[0], a[2]};
            break;
        case 71: // OpDecorate
            decorations_[{a[0], a[1]}] = a.size() > 2 ? a[2] : 1u;
            break;
        case 72: // OpMemberDecorate
            memberDecorations_[{a[0], a[1], a[2]}] = a.size() > 3 ? a[3] : 1u;
            break;
        default:
            break;
        }
    }
    uint32_t pointee(uint32_t pointerType) const { return pointers_.at(pointerType); }
    bool isBufferImage(uint32_t type) const {
        const uint32_t kDimBuffer = 5;
        const auto image = images_.find(type);
        return image != images_.end() && image->second.first == kDimBuffer;
    }
    std::optional<uint32_t> decoration(uint32_t id, uint32_t what) const {
        const auto it = decorations_.find({id, what});
        return it == decorations_.end() ? std::nullopt : std::optional<uint32_t>(it->second);
    }
    std::optional<uint32_t> memberDecoration(uint32_t type, uint32_t member, uint32_t what) const {
        const auto it = memberDecorations_.find({type, member, what});
        return it == memberDecorations_.end() ? std::nullopt : std::optional<uint32_t>(it->second);
    }

    std::map<uint32_t, uint32_t> scalars_;
    std::map<uint32_t, std::pair<uint32_t, uint32_t>> vectors_;
    std::map<uint32_t, uint32_t> sampledImages_;
    std::map<uint32_t, std::pair<uint32_t, uint32_t>> images_; // dim, image format
    std::map<uint32_t, uint32_t> runtimeArrays_;
    std::map<uint32_t, std::pair<uint32_t, uint32_t>> arrays_;
    std::map<uint32_t, uint32_t> constants_;
    std::map<uint32_t, std::vector<uint32_t>> structs_;
    std::map<uint32_t, uint32_t> pointers_;
    std::map<uint32_t, Variable> variables_;
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> decorations_;
    std::map<std::tuple<uint32_t, uint32_t, uint32_t>, uint32_t> memberDecorations_;
};

} // namespace cloudscape::testing
