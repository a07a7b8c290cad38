#pragma once
// Writes a scene as .cnb, our compact binary NURBS encoding (docs/cnb.md): control points quantised on
// the coarsest grid whose bound keeps every decoded surface, trimming boundary, curve and mesh within
// options.max_deviation of the original (cnb_quantisation.hpp), knots and weights exact, residuals of a
// prediction as zig-zag varints, then entropy-coded (deflate or our adaptive arithmetic coder).
// Kept: the node tree, names, colours (to 1/65535), transforms (exact), units, trimming loops with their
// shared-edge numbers, polygon and triangle meshes, 3D curves. Not kept: source_type, source_entity.
#include <string>

#include "core/scene.hpp"
#include "formats/cnb/cnb_options.hpp"

namespace cadnurbs {

// The file's bytes. Throws GeometryError for an invalid scene, std::invalid_argument for options out of
// range or a deviation so small that a coordinate would need more than 2^52 steps.
std::string write_cnb(const Scene& scene, const CnbOptions& options, CnbWriteReport* report = nullptr);

}  // namespace cadnurbs
