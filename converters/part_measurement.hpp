#pragma once
// The report's pipeline for one part: read it, write every representation the report compares into a
// folder, read each file back, and measure it (report/storage_record.hpp). Every byte count is a
// file's size on disk; every deviation is of what reading the file back gives: a bound wherever one
// exists (a certificate, a written precision, a quantisation replayed), else measured face by face.
#include <string>

#include "report/html/report_html.hpp"
#include "report/storage_record.hpp"
#include "converters/conversion_record.hpp"
#include "converters/file_formats.hpp"

namespace cadnurbs {

struct PartMeasurementOptions {
  double deviation_mm = 1.0;  // D, in millimetres (converted to the part's unit)
  // Where the representations are written (created if missing; files named after the input). Empty: a
  // temporary folder, removed afterwards.
  std::string files_folder;
  bool curve = false;         // also the storage-against-deviation curve (analysis of several D)
  // > 0: also the compact X3D NURBS with knots removed within this many millimetres (convert --simplify),
  // next to the source NURBS, its deviation certified by simplified_scene (converters/scene_preparation).
  double simplify_mm = 0;
  const FileFormat* format = nullptr;  // the input's format when its name does not say it (batch tells it by content)
  SceneReadOptions read;               // how the input is read (the STEP/IGES wall and its limits)
};

// The record of `input`. Never throws for a bad input: a file that cannot be read or measured gives a
// record with failed = true and the one-line reason (the error of the stage that failed). `views` (may be
// null): also the texts the HTML report draws, the compact X3D NURBS file and the mesh at D as X3D.
PartRecord measure_part(const std::string& input, const PartMeasurementOptions& options, PartViews* views = nullptr);

// The same for a part read already (`loaded`, as load_scene gives it): batch reads a part once for its
// record and its outputs.
PartRecord measure_loaded_part(const std::string& input, const BrepTranslation& loaded,
                               const PartMeasurementOptions& options, PartViews* views = nullptr);

}  // namespace cadnurbs
