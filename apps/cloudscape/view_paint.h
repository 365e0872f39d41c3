#pragma once
// Painting the weather map in the viewer: a round brush (radius in metres, strength in [-1, 1]:
// toward full or none) on one channel (coverage, precipitation or type), with undo, and the
// painted map saved as the PNG that weather.image reads. The brush's per-texel rule is the
// model's (src/model/brush.glsl.h). The map is painted on the host and uploaded whole
// (Renderer::replaceWeatherMap), one stroke a frame at most.
//
// The coverage bias (which makes the map's mean coverage weather.coverage) is held where it was:
// a stroke changes coverage inside the brush only, and weather.coverage becomes the painted
// map's new mean, so a scene saved with the painted map as its weather.image renders alike.
#include <cloudscape/persistent_renderer.h>
#include <cloudscape/scene.h>

#include <deque>
#include <string>

namespace cloudscape::cli {

struct BrushStroke {
    enum class Channel { Coverage, Precipitation, Type };
    Channel channel = Channel::Coverage;
    float xM = 0.0f; // world x and z of the centre
    float zM = 0.0f;
    float radiusM = 1000.0f;
    float strength = 0.5f;
};

// "coverage", "precipitation", "type"; throws cloudscape::Error naming the known ones.
BrushStroke::Channel brushChannel(const std::string& name);
const char* brushChannelName(BrushStroke::Channel channel);

// Refuses (one-line cloudscape::Error starting with `where`) a stroke whose centre lies outside
// the square the weather map covers, a radius not in (0, weather.extent_m] or a strength outside
// [-1, 1].
void checkStroke(const Scene& scene, const BrushStroke& stroke, const std::string& where);

class WeatherPainter {
public:
    // Paints the renderer's current map and uploads it; sets scene.coverage to the new mean.
    void paint(Renderer& renderer, Scene& scene, const BrushStroke& stroke);
    // Puts back the map (and weather.coverage) from before the last stroke; false if none.
    bool undo(Renderer& renderer, Scene& scene);
    // The map was made anew (a weather key changed): the strokes cannot be undone any more.
    void forget() { history_.clear(); }
    size_t undoSteps() const { return history_.size(); }
    int strokes() const { return strokes_; }
    // Wall time of the strokes and undos so far, host and device (an edit waits for its upload):
    // what a person painting waits for, a stroke a frame.
    double editSeconds() const { return editSeconds_; }
    int edits() const { return edits_; }

    // Level 0 of `map` as an RGB PNG (coverage field, precipitation, type in 8 bits; what
    // loadWeatherImage reads), written atomically.
    static void saveImage(const Texture2D& map, const std::string& path);

private:
    struct Step {
        Texture2D map;
        float coverage = 0.0f;
    };
    std::deque<Step> history_; // the newest last; the oldest dropped past kUndoSteps
    int strokes_ = 0;
    double editSeconds_ = 0.0;
    int edits_ = 0;
};

} // namespace cloudscape::cli
