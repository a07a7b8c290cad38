#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>

#include "report/report_formats.hpp"
#include "converters/arguments.hpp"
#include "converters/commands.hpp"
#include "converters/part_measurement.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

const CommandSpec& report_command_spec() {
  static const CommandSpec spec = {
      "report",
      "IN... [options]",
      "For each part: what NURBS and meshes cost at the same accuracy, in floats (counted as seed 001,\n"
      "6.1 counts them) and in bytes of files actually written and read back (raw and gzip'd), with the\n"
      "deviation of each file from the part: a bound wherever one exists, else measured face by face.",
      with_read_limits({
          {"deviation", "D", "the maximum deviation D of every mesh, in millimetres (default 1)"},
          {"format", "F",
           "md (default), json, csv or html (one self-contained page: charts and the\n"
           "part drawn as NURBS and as mesh); by default the extension of -o decides"},
          {"output", "FILE", "write the report there (default: standard output)"},
          {"files", "DIR", "keep the written representations in DIR (default: a temporary folder)"},
          {"records", "DIR", "also one JSON record per part in DIR (NAME.json)"},
          {"curve", "", "also bytes against D, from 1 % of the part's diagonal down to 1e-5 of it"},
          {"simplify", "S",
           "also the compact X3D NURBS with the knots removed that no face needs\n"
           "within S millimetres (convert --simplify), next to the source NURBS"},
      }),
      "Goes on past a file that fails and lists it with its reason; the exit status is 0 when every\n"
      "part was measured, 3 when some failed.",
  };
  return spec;
}

namespace {

struct Layout {
  std::string (*write)(const std::vector<PartRecord>&, const std::vector<PartViews>&);
  bool draws_parts;  // needs the scene texts of the 3D views
};
const std::map<std::string, Layout>& layouts() {
  static const std::map<std::string, Layout> table = {
      {"md", {[](const auto& records, const auto&) { return report_markdown(records); }, false}},
      {"json", {[](const auto& records, const auto&) { return report_json(records); }, false}},
      {"csv", {[](const auto& records, const auto&) { return report_csv(records); }, false}},
      {"html", {[](const auto& records, const auto& views) { return report_html(records, views); }, true}},
  };
  return table;
}

// --format, else the extension of -o, else Markdown.
std::string layout_name(const Arguments& a) {
  if (a.has("format")) return a.value("format");
  if (a.has("output")) {
    const std::string extension = file_extension(a.value("output"));
    if (extension.size() > 1 && layouts().count(extension.substr(1))) return extension.substr(1);
  }
  return "md";
}

constexpr int kSomeFailed = 3;

}  // namespace

int run_report(const std::vector<std::string>& args, const CommandContext& context) {
  const Arguments a = parse_arguments(report_command_spec(), args);
  if (a.has("help")) {
    std::cout << command_help(report_command_spec());
    return 0;
  }
  const SceneReadOptions read = scene_read_options(a, context);
  if (a.positional.empty()) throw UsageError("needs at least one input (see --help)");
  const std::string layout = layout_name(a);
  if (!layouts().count(layout)) throw UsageError("--format: unknown format '" + layout + "' (md, json, csv, html)");
  const Layout& chosen = layouts().at(layout);
  PartMeasurementOptions options;
  options.read = read;
  options.deviation_mm = a.number("deviation", 1.0);
  if (!(options.deviation_mm > 0) || !std::isfinite(options.deviation_mm))
    throw UsageError("--deviation must be a positive number of millimetres");
  options.curve = a.has("curve");
  options.simplify_mm = a.number("simplify", 0.0);
  if (a.has("simplify") && !(options.simplify_mm > 0 && std::isfinite(options.simplify_mm)))
    throw UsageError("--simplify must be a positive number of millimetres");
  std::vector<PartRecord> records;
  std::vector<PartViews> views;
  int failed = 0;
  std::map<std::string, int> names_used;  // parts of a library may share a name in different folders
  for (const auto& input : a.positional) {
    std::string name = std::filesystem::path(input).stem().string();
    if (const int n = ++names_used[name]; n > 1) name += "-" + std::to_string(n);
    if (a.has("files")) options.files_folder = (std::filesystem::path(a.value("files")) / name).string();
    PartViews part_views;
    records.push_back(measure_part(input, options, chosen.draws_parts ? &part_views : nullptr));
    if (chosen.draws_parts) views.push_back(std::move(part_views));
    if (records.back().failed) {
      ++failed;
      std::cerr << "cadnurbs report: " << input << ": " << records.back().error << "\n";
    }
    if (a.has("records")) {
      std::filesystem::create_directories(a.value("records"));
      write_file_atomically((std::filesystem::path(a.value("records")) /
                             (name + ".json")).string(),
                            part_record_json(records.back()));
    }
  }
  const std::string text = chosen.write(records, views);
  if (a.has("output"))
    write_file_atomically(a.value("output"), text);
  else
    std::cout << text;
  if (failed > 0) {
    std::cerr << "cadnurbs report: " << failed << " of " << records.size() << " inputs failed\n";
    return kSomeFailed;
  }
  return 0;
}

}  // namespace cadnurbs
