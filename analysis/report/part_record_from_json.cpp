#include "analysis/report/part_record_from_json.hpp"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace cadnurbs {

namespace {

using Json = nlohmann::json;

double number_or_nan(const Json& value) {
  return value.is_null() ? std::numeric_limits<double>::quiet_NaN() : value.get<double>();
}

RepresentationKind kind_named(const std::string& name) {
  if (name == "nurbs") return RepresentationKind::nurbs;
  if (name == "mesh") return RepresentationKind::mesh;
  if (name == "nurss") return RepresentationKind::nurss;
  if (name == "loop") return RepresentationKind::loop;
  throw std::invalid_argument("unknown representation kind '" + name + "'");
}

NurbsStorage nurbs_from(const Json& j) {
  NurbsStorage s;
  s.surfaces = j.at("surfaces").get<long>();
  s.control_points = j.at("control_points").get<long>();
  s.knots = j.at("knots").get<long>();
  s.floats = j.at("floats").get<long>();
  s.trim_curves = j.at("trim_curves").get<long>();
  s.trim_control_points = j.at("trim_control_points").get<long>();
  s.trim_knots = j.at("trim_knots").get<long>();
  s.trim_polyline_points = j.at("trim_polyline_points").get<long>();
  s.trim_floats = j.at("trim_floats").get<long>();
  s.polygon_vertices = j.at("polygon_vertices").get<long>();
  s.polygon_corners = j.at("polygon_corners").get<long>();
  s.polygon_floats = j.at("polygon_floats").get<long>();
  return s;
}

MeshStorage mesh_from(const Json& j) {
  MeshStorage s;
  s.vertices = j.at("vertices").get<long>();
  s.triangles = j.at("triangles").get<long>();
  s.indexed_floats = j.at("indexed_floats").get<long>();
  s.indexed_integers = j.at("indexed_integers").get<long>();
  s.indexed_floats_with_normals = j.at("indexed_floats_with_normals").get<long>();
  s.soup_floats = j.at("soup_floats").get<long>();
  s.soup_floats_with_normals = j.at("soup_floats_with_normals").get<long>();
  return s;
}

PartRecord record_from(const Json& j) {
  PartRecord r;
  r.input = j.at("input").get<std::string>();
  r.failed = j.at("status").get<std::string>() != "ok";
  if (r.failed) {
    r.error = j.at("error").get<std::string>();
    return r;
  }
  r.unit = j.at("unit").get<std::string>();
  r.diagonal = j.at("diagonal").get<double>();
  r.deviation = j.at("deviation").get<double>();
  r.nurbs = nurbs_from(j.at("nurbs"));
  r.compact_nurbs = nurbs_from(j.at("compact_nurbs"));
  r.mesh = mesh_from(j.at("mesh"));
  r.mesh_certified_deviation = j.at("mesh").at("certified_deviation").get<double>();
  for (const Json& f : j.at("representations")) {
    RepresentationFigures figures;
    figures.key = f.at("key").get<std::string>();
    figures.label = f.at("label").get<std::string>();
    figures.kind = kind_named(f.at("kind").get<std::string>());
    figures.bytes = f.at("bytes").get<long>();
    figures.gzip_bytes = f.at("gzip_bytes").get<long>();
    figures.floats = f.at("floats").get<long>();
    figures.integers = f.at("integers").get<long>();
    figures.deviation = number_or_nan(f.at("deviation"));
    figures.deviation_basis = f.at("deviation_basis").get<std::string>();
    r.representations.push_back(std::move(figures));
  }
  for (const Json& p : j.at("curve"))
    r.curve.push_back({p.at("key").get<std::string>(), p.at("deviation").get<double>(), p.at("bytes").get<long>(),
                       p.at("gzip_bytes").get<long>(), p.at("floats").get<long>()});
  for (const Json& c : j.at("crossovers"))
    r.crossovers.push_back({c.at("mesh_key").get<std::string>(), c.at("nurbs_key").get<std::string>(),
                            c.at("nurbs_bytes").get<long>(), number_or_nan(c.at("deviation")),
                            c.at("mesh_larger_everywhere").get<bool>()});
  r.warnings = j.at("warnings").get<std::vector<std::string>>();
  return r;
}

}  // namespace

PartRecord part_record_from_json(const std::string& text, const std::string& name) {
  try {
    return record_from(Json::parse(text));
  } catch (const std::exception& error) {
    throw std::invalid_argument(name + ": not a part record (" + error.what() + ")");
  }
}

}  // namespace cadnurbs
