#include <filesystem>
#include <iomanip>
#include <iostream>

#include "converters/arguments.hpp"
#include "report/report_formats.hpp"
#include "converters/capping_files.hpp"
#include "converters/commands.hpp"
#include "converters/part_measurement.hpp"
#include "formats/common/file_io.hpp"
#include "samples/capping_shapes.hpp"

namespace cadnurbs {

// The description tells what DIR is: -o needs no line of its own.
const CommandSpec& demo_command_spec() {
  static const CommandSpec spec = {
      "demo",
      "[-o DIR]",
      "The main job on the bundled samples: generates every bundled stair capping as NURBS (.wrl .x3dv\n"
      ".x3d), as B-rep (.step .iges) and as STL (thesis chord rule, 1 mm), and prints for each the\n"
      "counts the thesis uses (seed 001, 6.1): control points, knots, and floats = 4 per control point\n"
      "(x, y, z, w) + 1 per knot, against 3 floats per vertex of the triangle mesh. It ends with the\n"
      "storage report of the cappings (cadnurbs report at D = 1 mm: bytes of files written and read\n"
      "back), written to DIR/report.md, and prints its table. Default DIR: cadnurbs-demo.",
      {{"output", "DIR", ""}},
      "",
  };
  return spec;
}

namespace {
constexpr double kDemoChordDeviation = 1.0;  // the thesis's mesh comparison uses <= 1 mm
constexpr double kFineChordDeviation = 0.1;  // and a finer mesh, for how the balance moves
}  // namespace

int run_demo(const std::vector<std::string>& args, const CommandContext&) {
  const Arguments a = parse_arguments(demo_command_spec(), args);
  if (a.has("help")) {
    std::cout << command_help(demo_command_spec());
    return 0;
  }
  const std::string dir = a.value("output", "cadnurbs-demo");
  std::cout << "Stair cappings: storage as counted in seed 001, 6.1 (surfaces; trimming curves apart)\n";
  std::cout << std::left << std::setw(17) << "capping" << std::right << std::setw(9) << "surfaces" << std::setw(12)
            << "ctrl pts" << std::setw(8) << "knots" << std::setw(13) << "NURBS floats" << std::setw(12)
            << "trim floats" << std::setw(14) << "mesh vertices" << std::setw(12) << "mesh floats" << std::setw(8)
            << "ratio" << std::setw(18) << "floats @0.1 mm" << std::setw(8) << "ratio" << "\n";
  for (const auto& name : capping_shape_names()) {
    const CappingDefinition capping = bundled_capping(name);
    const SceneCounts c = count_entities(capping_nurbs(capping));
    const TriangleMesh mesh = capping_mesh(capping, kDemoChordDeviation);
    const long nurbs_floats = 4 * c.control_points + c.knots;
    const long trim_floats = 3 * c.trim_control_points + c.trim_knots;  // (u, v, w) + knots
    const long mesh_floats = 3 * static_cast<long>(mesh.positions.size());
    const long fine_floats = 3 * static_cast<long>(capping_mesh(capping, kFineChordDeviation).positions.size());
    const double nurbs_total = double(nurbs_floats + trim_floats);
    std::cout << std::left << std::setw(17) << name << std::right << std::setw(9) << c.surfaces << std::setw(12)
              << c.control_points << std::setw(8) << c.knots << std::setw(13) << nurbs_floats << std::setw(12)
              << trim_floats << std::setw(14) << mesh.positions.size() << std::setw(12) << mesh_floats << std::setw(8)
              << std::fixed << std::setprecision(2) << mesh_floats / nurbs_total << std::setw(18) << fine_floats
              << std::setw(8) << fine_floats / nurbs_total << std::defaultfloat << "\n";
  }
  std::cout << "(ratio = mesh floats / (NURBS + trim floats); meshes: STL chord rule at " << kDemoChordDeviation
            << " mm and " << kFineChordDeviation << " mm)\n\nFiles written:\n";
  for (const auto& name : capping_shape_names())
    for (const auto& path : write_capping_set(bundled_capping(name), dir, kDemoChordDeviation))
      std::cout << "  " << path << "  " << std::filesystem::file_size(path) << " bytes\n";

  PartMeasurementOptions options;
  options.deviation_mm = kDemoChordDeviation;
  std::vector<PartRecord> records;
  for (const auto& name : capping_shape_names())
    records.push_back(measure_part((std::filesystem::path(dir) / (name + ".x3dv")).string(), options));
  const std::string report = (std::filesystem::path(dir) / "report.md").string();
  write_file_atomically(report, report_markdown(records));
  std::cout << "\nStorage report at D = " << kDemoChordDeviation << " mm (" << report << "):\n\n"
            << report_markdown_parts(records);
  for (const auto& r : records)
    if (r.failed) throw std::runtime_error(r.input + ": " + r.error);
  return 0;
}

}  // namespace cadnurbs
