#include "converters/path_fitting.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "analysis/fitting/fit_position_path.hpp"
#include "core/geometry_error.hpp"
#include "formats/vrml/interpolators_in_text.hpp"
#include "formats/vrml/nurbs_interpolator_text.hpp"
#include "formats/vrml/xml_encoding.hpp"

namespace cadnurbs {

namespace {

// The written numbers' share of the deviation (per coordinate; the fit gets most of the rest).
constexpr double kRoundingShare = 0.05;

struct Replacement {
  size_t begin, end;
  std::string text;
};

std::string spliced(const std::string& text, const std::vector<Replacement>& replacements) {
  std::string out;
  size_t at = 0;
  for (const Replacement& r : replacements) {  // in file order, never overlapping
    out.append(text, at, r.begin - at);
    out += r.text;
    at = r.end;
  }
  out.append(text, at, std::string::npos);
  return out;
}

}  // namespace

PathRewrite fit_paths_in_text(const std::string& text, VrmlEncoding encoding, double deviation,
                              const std::string& protos_url, const std::string& name_for_errors) {
  if (!(deviation > 0)) throw std::invalid_argument("the deviation must be > 0");
  const bool xml = encoding == VrmlEncoding::x3d_xml;
  const std::vector<InterpolatorInText> nodes = find_interpolators(text, xml, name_for_errors);
  const auto tolerances = [&](const NurbsCurve& curve) {
    return curve_tolerances(curve, kRoundingShare * deviation, /*homogeneous=*/false);
  };

  PathRewrite rewrite;
  std::vector<Replacement> replacements;
  std::set<std::string> converted_defs;  // for XML USEs of them
  for (const InterpolatorInText& node : nodes) {
    if (!node.use_name.empty()) continue;
    PathAccount account;
    account.type = node.type;
    account.def_name = node.def_name;
    account.line = node.line;
    account.bytes_before = account.bytes_after = node.end - node.begin;
    const int tuple = node.type == "PositionInterpolator" ? 3 : 4;
    account.keys = static_cast<int>(node.key.size());
    if (node.type != "PositionInterpolator") {
      account.left_because = "NurbsOrientationInterpolator gives the rotation from +Z to the curve's tangent, "
                             "which cannot hold a roll about the path";
    } else if (!node.unconvertible.empty()) {
      account.left_because = node.unconvertible;
    } else if (node.key_value.size() != node.key.size() * tuple) {
      account.left_because = std::to_string(node.key.size()) + " keys but " + std::to_string(node.key_value.size()) +
                             " keyValue numbers";
    } else {
      std::vector<Eigen::Vector3d> values(node.key.size());
      for (size_t i = 0; i < values.size(); ++i)
        values[i] = Eigen::Vector3d(node.key_value[3 * i], node.key_value[3 * i + 1], node.key_value[3 * i + 2]);
      try {
        const PositionPathFit fit = fit_position_path(
            node.key, values, deviation, [&](const NurbsCurve& c) { return as_written(c, tolerances(c)); });
        std::string replacement = nurbs_position_interpolator_text(fit.curve, node.def_name, encoding,
                                                                   tolerances(fit.curve), node.container_field);
        if (replacement.size() >= account.bytes_before) {
          account.left_because = "the NURBS would take " + std::to_string(replacement.size()) + " bytes, not fewer";
        } else {
          account.converted = true;
          account.control_points = fit.curve.count();
          account.order = fit.curve.order;
          account.max_error = fit.max_error;
          account.bytes_after = replacement.size();
          converted_defs.insert(node.def_name);
          replacements.push_back({node.begin, node.end, std::move(replacement)});
        }
      } catch (const GeometryError& e) {
        account.left_because = e.reason();
      }
    }
    rewrite.accounts.push_back(std::move(account));
  }
  // XML USEs of a rewritten node carry its element name.
  for (const InterpolatorInText& node : nodes) {
    if (node.use_name.empty() || !converted_defs.count(node.use_name) || node.type != "PositionInterpolator")
      continue;
    std::string element = "<NurbsPositionInterpolator USE='" + xml_escaped(node.use_name) + "'";
    if (!node.container_field.empty()) element += " containerField='" + xml_escaped(node.container_field) + "'";
    replacements.push_back({node.begin, node.end, element + "/>"});
  }
  std::sort(replacements.begin(), replacements.end(),
            [](const Replacement& a, const Replacement& b) { return a.begin < b.begin; });
  rewrite.text = replacements.empty() ? text
                                      : with_nurbs_interpolator_declared(spliced(text, replacements), encoding, protos_url);
  return rewrite;
}

}  // namespace cadnurbs
