#include "report/report_formats.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/number_format.hpp"
#include "report/record_fields.hpp"
#include "report/reference_figures.hpp"

namespace cadnurbs {

using Json = nlohmann::ordered_json;

namespace {

// The record's object: its status, then its error or its figures (record_fields.hpp names the keys).
Json record_json(const PartRecord& r) {
  Json j = Json::object();
  write_json_fields(part_status_fields(), r, j);
  write_json_fields(part_outcome_fields(r), r, j);
  return j;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// Markdown table cells must not contain '|'.
std::string cell(std::string text) {
  std::replace(text.begin(), text.end(), '|', '/');
  return text;
}

}  // namespace

std::string report_number(double value, int digits) { return std::isnan(value) ? "-" : number_text(value, digits); }

std::string labelled_deviation(const RepresentationFigures& figures) {
  if (std::isnan(figures.deviation)) return "-";
  return report_number(figures.deviation) + " " + deviation_kind_name(figures.deviation_kind);
}

const std::string& accounting_rule() {
  static const std::string rule =
      "Floats are counted as in seed 001, §6.1: NURBS = 4 per control point (x, y, z, w) + 1 per knot; trimming "
      "curves apart (3 per 2D control point + 1 per knot, 2 per polyline point); exact planar polygons apart (3 "
      "per vertex, corners as integers); mesh = 3 per welded vertex + 3 integers per triangle (STL soup: 9 per "
      "triangle, 12 with normals). Bytes are those of files actually written and read back; gzip at level 9.";
  return rule;
}

std::string part_record_json(const PartRecord& record) { return record_json(record).dump(2) + "\n"; }

std::string report_json(const std::vector<PartRecord>& records) {
  Json references = Json::array();
  for (const auto& f : reference_figures())
    references.push_back(Json{{"source", f.source}, {"part", f.part}, {"quantity", f.quantity}, {"value", f.value}});
  Json parts = Json::array();
  for (const auto& r : records) parts.push_back(record_json(r));
  const Json report{{"cadnurbs_report", 1},
                    {"accounting", accounting_rule()},
                    {"reference_figures", references},
                    {"parts", parts}};
  return report.dump(2) + "\n";
}

std::string report_csv(const std::vector<PartRecord>& records) {
  std::vector<std::string> keys;  // representations in the order of first appearance
  for (const auto& r : records)
    for (const auto& f : r.representations)
      if (std::find(keys.begin(), keys.end(), f.key) == keys.end()) keys.push_back(f.key);
  std::string header =
      "input,status,error,unit,diagonal,deviation,control_points,knots,nurbs_floats,trim_floats,polygon_floats,"
      "mesh_vertices,mesh_triangles,mesh_indexed_floats,mesh_indexed_integers,mesh_soup_floats,"
      "mesh_certified_deviation";
  for (const auto& k : keys)
    header += "," + k + ".bytes," + k + ".gzip_bytes," + k + ".deviation," + k + ".deviation_kind";
  // A failed part fills the columns after its error with empty fields.
  const auto columns_after_error = std::count(header.begin(), header.end(), ',') - 2;
  std::ostringstream out;
  out << header << "\n" << std::setprecision(8);
  for (const auto& r : records) {
    out << csv_field(r.input) << "," << (r.failed ? "failed" : "ok") << "," << csv_field(r.error);
    if (r.failed) {
      out << std::string(columns_after_error, ',') << "\n";
      continue;
    }
    out << "," << r.unit << "," << r.diagonal << "," << r.deviation << "," << r.nurbs.control_points << ","
        << r.nurbs.knots << "," << r.nurbs.floats << "," << r.nurbs.trim_floats << "," << r.nurbs.polygon_floats << ","
        << r.mesh.vertices << "," << r.mesh.triangles << "," << r.mesh.indexed_floats << "," << r.mesh.indexed_integers
        << "," << r.mesh.soup_floats << "," << r.mesh_certified_deviation;
    for (const auto& k : keys) {
      if (const auto* f = find_representation(r, k))
        out << "," << f->bytes << "," << f->gzip_bytes << ","
            << (std::isnan(f->deviation) ? "," : report_number(f->deviation, 8) + "," + deviation_kind_name(f->deviation_kind));
      else
        out << ",,,,";
    }
    out << "\n";
  }
  return out.str();
}

std::string report_markdown_parts(const std::vector<PartRecord>& records) {
  std::ostringstream out;
  out << "| part | D | NURBS floats | trim floats | mesh floats at D | smallest NURBS file | bytes | smallest mesh file | "
         "bytes | mesh / NURBS |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : records) {
    if (r.failed) continue;
    const auto* nurbs = smallest_representation(r, RepresentationKind::nurbs);
    const auto* mesh = smallest_representation(r, RepresentationKind::mesh);
    out << "| " << cell(r.input) << " | " << report_number(r.deviation) << " " << r.unit << " | " << r.nurbs.floats << " | "
        << r.nurbs.trim_floats << " | " << r.mesh.indexed_floats << " | " << (nurbs ? nurbs->label : "-") << " | "
        << (nurbs ? std::to_string(delivered_bytes(*nurbs)) : "-") << " | " << (mesh ? mesh->label : "-") << " | "
        << (mesh ? std::to_string(delivered_bytes(*mesh)) : "-") << " | "
        << (nurbs && mesh ? report_number(double(delivered_bytes(*mesh)) / double(delivered_bytes(*nurbs)), 3) : "-") << " |\n";
  }
  out << "\n(smallest file: the smaller of the file and its gzip'd form, over every representation of that kind)\n";
  return out.str();
}

std::string report_markdown(const std::vector<PartRecord>& records) {
  std::ostringstream out;
  out << "# cadnurbs storage report\n\n" << accounting_rule() << "\n\n## Parts\n\n" << report_markdown_parts(records);
  const auto failed = std::count_if(records.begin(), records.end(), [](const PartRecord& r) { return r.failed; });
  if (failed > 0) {
    out << "\n## Failed (" << failed << ")\n\n";
    for (const auto& r : records)
      if (r.failed) out << "- " << r.input << ": " << r.error << "\n";
  }
  for (const auto& r : records) {
    if (r.failed) continue;
    out << "\n## " << r.input << "\n\n"
        << "Maximum deviation D = " << report_number(r.deviation) << " " << r.unit << " (bounding-box diagonal "
        << report_number(r.diagonal) << " " << r.unit << "). NURBS: " << r.nurbs.surfaces << " surfaces, "
        << r.nurbs.control_points << " control points, " << r.nurbs.knots << " knots; compact form "
        << r.compact_nurbs.control_points << " control points, " << r.compact_nurbs.knots << " knots, "
        << r.compact_nurbs.polygon_vertices << " polygon vertices. Mesh at D: " << r.mesh.vertices << " vertices, "
        << r.mesh.triangles << " triangles (certified " << report_number(r.mesh_certified_deviation) << ").\n\n"
        << "| representation | bytes | gzip'd | floats | integers | deviation | how the deviation is known |\n"
           "|---|---|---|---|---|---|---|\n";
    for (const auto& f : r.representations)
      out << "| " << f.label << " | " << f.bytes << " | " << f.gzip_bytes << " | " << f.floats << " | " << f.integers
          << " | " << labelled_deviation(f) << " | " << cell(f.deviation_basis) << " |\n";
    if (!r.curve.empty()) {
      out << "\nStorage against accuracy (certified mesh at each D, delivered = smaller of raw and gzip'd):\n\n"
             "| representation | D | bytes | gzip'd | floats |\n|---|---|---|---|---|\n";
      for (const auto& p : r.curve)
        out << "| " << p.key << " | " << report_number(p.deviation) << " | " << p.bytes << " | " << p.gzip_bytes << " | "
            << p.floats << " |\n";
      for (const auto& c : r.crossovers) {
        out << "\n" << c.mesh_key << " against " << c.nurbs_key << " (" << c.nurbs_bytes << " bytes): ";
        if (!std::isnan(c.deviation))
          out << "the mesh costs more below D = " << report_number(c.deviation, 3) << " " << r.unit << ".\n";
        else if (c.mesh_larger_everywhere)
          out << "the mesh costs more at every D measured.\n";
        else
          out << "the mesh costs less at every D measured.\n";
      }
    }
    if (!r.warnings.empty()) {
      out << "\nReader's notes:\n\n";
      for (const auto& w : r.warnings) out << "- " << w << "\n";
    }
  }
  out << "\n## Reference figures (the papers' own, not measured here)\n\n| source | part | quantity | value |\n"
         "|---|---|---|---|\n";
  for (const auto& f : reference_figures())
    out << "| " << f.source << " | " << f.part << " | " << f.quantity << " | " << f.value << " |\n";
  return out.str();
}

}  // namespace cadnurbs
