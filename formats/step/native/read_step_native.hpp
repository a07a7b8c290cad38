#pragma once
// Our own STEP reader: the ISO 10303-21 file parsed into an entity table (formats/step/part21), its
// B-rep built straight into a Scene of trimmed NURBS, no OpenCASCADE. Reads the subset part libraries use:
// one product whose shape representation (or one related to it) holds MANIFOLD_SOLID_BREPs,
// BREP_WITH_VOIDS without voids... , or SHELL_BASED_SURFACE_MODELs of ADVANCED_FACEs on planes, cylinders,
// cones, spheres, tori, surfaces of revolution and of linear extrusion and B-spline surfaces, bounded by
// edges on lines, circles, ellipses and B-spline curves; colours from the presentation; SI and
// conversion-based units. Trimming curves are computed (native_face).
#include <string>

#include "formats/brep/brep_translation.hpp"
#include "formats/step/native/step_context.hpp"

namespace cadnurbs {

// Takes the path of a STEP file. Returns the same translation the OpenCASCADE path gives (formats/step/
// step_reader.hpp): root named after the product (else the file's stem), one solid's or shell's faces as
// the root's shapes ("face N", its surface type as OpenCASCADE names it), several as children "solid K" /
// "shell K"; face colours, else the solid's as the node's; millimetres, source_unit the file's.
// Refuses: FileError for a file that is not valid ISO 10303-21 (parse_part21's messages); 
// step::OutsideNativeSubset ("#N TYPE: reason") for anything outside the subset or a face it cannot
// convert: the caller hands the file to OpenCASCADE.
BrepTranslation read_step_native(const std::string& path);

}  // namespace cadnurbs
