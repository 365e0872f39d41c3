#pragma once
// The real-time march's empty-space grid (model/cloud_bound.glsl.h): the altitude above which
// each column of the cloud layer is provably empty, from the weather map through the model's own
// bound (the one the path tracer's majorant grid uses).
#include <cloudscape/texture.h>
#include <cloudscape/weather.h>

#include "model/params.glsl.h"

namespace cloudscape {

// Fills p.cloudTops, p.cloudNoiseLevels and p.cloudTopMax from the weather map for p's coverage
// bias, type offset, layer and storm (all of p must be set first); does not switch skipping on.
// With `cells` made for this map (weatherCellMaxima) the map is not read again.
void fillCloudTopGrid(model::CloudParams& p, const Texture2D& weather,
                      const WeatherCellMaxima* cells = nullptr);

// The map's level 0 changed inside columns [x0, x1) and rows [y0, y1) (an edit in place): the
// cells whose bilinear reads can touch those texels are made again, and `cells` is marked as
// made for the edited map. Cells made for another map are made whole.
void refreshWeatherCells(WeatherCellMaxima& cells, const Texture2D& weather, int x0, int y0, int x1,
                         int y1);

} // namespace cloudscape
