#pragma once
// A small picture of a part for a library's index (`batch --site`): its certified mesh (web/api, the mesh the
// browser module draws) seen as the viewer first shows it (web/viewer's fit to view: the bounding sphere
// filling a 35-degree view from the direction (1, -1.4, 0.9), z up), each triangle flat-shaded in its face's
// colour by a light over the viewer's shoulder, on white. Pixels are whole (no antialiasing) and shades come
// in a few steps, so that the picture has few colours and its PNG (formats/png) costs a few kilobytes.
#include "formats/png/indexed_png.hpp"
#include "web/api/scene_arrays.hpp"

namespace cadnurbs {

constexpr int thumbnail_shades = 6;  // steps of light per face colour

// The picture, width x height pixels. A mesh of no triangle gives a white picture. Throws
// std::invalid_argument for a size below 1 x 1.
IndexedImage part_thumbnail(const SceneArrays& mesh, int width, int height);

}  // namespace cadnurbs
