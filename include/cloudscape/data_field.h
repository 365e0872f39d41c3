#pragma once
// The Nubis data field's extra channels (src/model/data_field.glsl.h): per region of the weather
// map a bottom type, an anvil (superstorm) coverage and the clouds' minimum and maximum heights as
// fractions of the layer's depth. DATA_FIELD_GRID^2 regions tiling the map, row-major in
// weather-map (x, z), one vec4 each; they reach the model in its parameter block.
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace cloudscape {

// The generator's inputs, the weather.* keys of a scene (defaults and ranges are the key table's).
struct DataFieldParams {
    uint32_t seed = 1;
    float extentM = 60000.0f;      // the weather map's extent (m)
    float featureScaleM = 6000.0f; // its coverage features' size (m): regions vary 3x slower
    float bottomType = 0.0f;       // mean bottom type
    float baseVariation = 0.0f;    // most the base is raised, fraction of the layer
    float topVariation = 0.0f;     // most the top is lowered, fraction of the layer
};

// Tileable noises composited into the channels: bottom type about its mean (0 stays 0), the base
// raised by up to baseVariation and the top lowered by up to topVariation, each by its own FBM;
// no anvil (the storm's stencil is composited by the model, per sample). All parameters at their
// defaults give the neutral field. Throws cloudscape::Error naming a key out of its range.
std::vector<glm::vec4> generateDataField(const DataFieldParams& params);

// Painted override: an RGBA PNG (R bottom type, G anvil coverage, B minimum height, A maximum
// height; 8-bit linear fractions), or RGB (maximum height 1), stretched over the weather map's
// extent and averaged onto the regions. Throws cloudscape::Error naming the file on an unreadable
// image or another channel count.
std::vector<glm::vec4> loadDataFieldImage(const std::string& path);

// Whether every region holds the neutral value (0, 0, 0, 1): the model is then exactly the one
// without a data field, and it is switched off.
bool isNeutralDataField(const std::vector<glm::vec4>& field);

} // namespace cloudscape
