#pragma once
// Our own STEP reader: the ISO 10303-21 file parsed into an entity table (formats/step/part21), its
// B-rep built straight into a Scene of trimmed NURBS, no OpenCASCADE. Reads the subset part libraries use:
// products and their assemblies (step_assembly: NEXT_ASSEMBLY_USAGE_OCCURRENCEs placed by
// ITEM_DEFINED_TRANSFORMATIONs), each part's shape representations holding MANIFOLD_SOLID_BREPs,
// BREP_WITH_VOIDS or SHELL_BASED_SURFACE_MODELs of ADVANCED_FACEs on planes, cylinders, cones, spheres,
// tori, surfaces of revolution and of linear extrusion and B-spline surfaces, bounded by edges on lines,
// circles, ellipses and B-spline curves; colours from the presentation; SI and conversion-based units, per
// representation. Trimming curves are computed (native_face).
#include <string>
#include <string_view>

#include "formats/brep/brep_translation.hpp"
#include "formats/step/native/step_context.hpp"

namespace cadnurbs {

// Takes the path of a STEP file. Returns the same translation the OpenCASCADE path gives (formats/step/
// step_reader.hpp + xcaf_to_scene): the root named after its product (else the file's stem), or, for
// several top-level products, a root named after the stem with one child each; an assembly's components
// as children named after the occurrence (else their product), transformed by their placements; a part's
// one solid's or shell's faces as the node's shapes ("face N", its surface type as OpenCASCADE names it),
// several as children "solid K" / "shell K"; a part placed several times is converted once and copied;
// face colours, else the solid's as the node's; millimetres, source_unit that of the first root's shape.
// Refuses: FileError for a file that is not valid ISO 10303-21 (parse_part21's messages);
// step::OutsideNativeSubset ("#N TYPE: reason") for anything outside the subset or a face it cannot
// convert: the caller hands the file to OpenCASCADE.
BrepTranslation read_step_native(const std::string& path);

// The same for the file's bytes, already read (`path` names the file in messages and gives the stem).
BrepTranslation read_step_native(std::string_view bytes, const std::string& path);

}  // namespace cadnurbs
