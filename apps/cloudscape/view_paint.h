#pragma once
// Painting the weather map in the viewer: a round brush (radius in metres, strength in [-1, 1]:
// toward full or none) on one channel (coverage, precipitation or type, or one of the data
// field's: bottom type, anvil coverage, minimum or maximum height), with undo, and the painted
// map saved as the PNG that weather.image reads (the field as the PNG weather.field_image reads).
// The brush's per-texel rule is the model's (src/model/brush.glsl.h). A stroke paints only the
// texels under the brush's square (at every mip level, from an unrounded copy of the chain, so the
// texels are those that buildMipChain and quantizeToUnorm8 make of the whole painted map) and hands
// them to Renderer::editWeatherMap, which copies just them into the device's image.
//
// The coverage bias (which makes the map's mean coverage weather.coverage) is held where it was:
// a stroke changes coverage inside the brush only, and weather.coverage becomes the painted
// map's new mean, so a scene saved with the painted map as its weather.image renders alike.
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/scene.h>

#include <deque>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace cloudscape::cli {

struct BrushStroke {
    enum class Channel {
        Coverage,
        Precipitation,
        Type,
        // The data field's (src/model/data_field.glsl.h), painted on the host's 64^2 regions.
        BottomType,
        AnvilCoverage,
        MinHeight,
        MaxHeight
    };
    Channel channel = Channel::Coverage;
    float xM = 0.0f; // world x and z of the centre
    float zM = 0.0f;
    float radiusM = 1000.0f;
    float strength = 0.5f;
};

// "coverage", "precipitation", "type", "bottom_type", "anvil", "min_height", "max_height";
// throws cloudscape::Error naming the known ones.
BrushStroke::Channel brushChannel(const std::string& name);
const char* brushChannelName(BrushStroke::Channel channel);
const std::vector<BrushStroke::Channel>& brushChannels();
bool isDataFieldChannel(BrushStroke::Channel channel);

// Refuses (one-line cloudscape::Error starting with `where`) a stroke whose centre lies outside
// the square the weather map covers, a radius not in (0, weather.extent_m] or a strength outside
// [-1, 1].
void checkStroke(const Scene& scene, const BrushStroke& stroke, const std::string& where);

// Reads the device's weather map back and compares every level, texel and channel with the
// host's copy (what the CPU backend, save-weather and the debug view read); throws a one-line
// cloudscape::Error starting with `where` at the first difference, else returns the texels
// compared (0 on the CPU backend, which has no device copy).
size_t checkDeviceWeather(const Renderer& renderer, const std::string& where);

class WeatherPainter {
public:
    // Paints the renderer's current map and uploads it; sets scene.coverage to the new mean.
    void paint(Renderer& renderer, Scene& scene, const BrushStroke& stroke);
    // Puts back the map (and weather.coverage) from before the last stroke; false if none.
    bool undo(Renderer& renderer, Scene& scene);
    // The map was made anew (a weather key changed): the strokes cannot be undone any more.
    void forget() {
        history_.clear();
        exact_ = {};
    }
    size_t undoSteps() const { return history_.size(); }
    int strokes() const { return strokes_; }
    // Wall time of the strokes and undos so far, host and device (an edit waits for its upload):
    // what a person painting waits for, a stroke a frame.
    double editSeconds() const { return editSeconds_; }
    int edits() const { return edits_; }

    // Level 0 of `map` as an RGB PNG (coverage field, precipitation, type in 8 bits; what
    // loadWeatherImage reads), written atomically.
    static void saveImage(const Texture2D& map, const std::string& path);
    // The data field's regions as the RGBA PNG loadDataFieldImage reads (one pixel a region;
    // the neutral field where `field` is empty), written atomically.
    static void saveFieldImage(const std::vector<glm::vec4>& field, const std::string& path);

private:
    // What a stroke changed: its level-0 rectangles and, level by level, the texels of their
    // footprints before it (the rounded map's and the unrounded chain's), in footprint order.
    struct Step {
        std::vector<TexelRect> rects;
        std::vector<std::vector<float>> map, exact;
        float coverage = 0.0f;
        std::vector<glm::vec4> field; // a data-field stroke: the regions before it
    };
    void paintField(Renderer& renderer, const Scene& scene, const BrushStroke& stroke);
    // The unrounded mip chain of the renderer's current map (buildMipChain of its level 0),
    // made at the first stroke on a map; level l's painted texels average level l - 1's.
    void prepareExact(const Renderer& renderer);
    std::deque<Step> history_; // the newest last; the oldest dropped past kUndoSteps
    Texture2D exact_;
    uint64_t exactVersion_ = 0; // Renderer::weatherMapVersion() exact_ was made for
    uint64_t fieldVersion_ = 0; // Renderer::dataFieldVersion() the field strokes were made on
    int strokes_ = 0;
    double editSeconds_ = 0.0;
    int edits_ = 0;
};

} // namespace cloudscape::cli
