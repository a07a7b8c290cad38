#include "converters/cnb_coding.hpp"

#include <limits>
#include <stdexcept>

#include "core/number_format.hpp"
#include "formats/cnb/cnb_writer.hpp"

namespace cadnurbs {

namespace {
// The share of D that trims (in (u,v)) and meshes (their certificate) may use; points get the rest.
constexpr double kMeshShare = 0.4;
}  // namespace

CnbCoding cnb_coding(const Scene& scene, double max_deviation, const Scene* exact, bool mesh_where_cheaper) {
  CnbCoding out;
  out.options.max_deviation = max_deviation;
  out.options.trim_share = kMeshShare;
  // A candidate the writer refuses (std::invalid_argument: options it cannot meet for that scene) is never
  // the cheapest; the scene as it is, if refused too, fails in the last write below with the writer's message.
  auto coded_bytes = [&](const Scene& s, double mesh_deviation) {
    CnbOptions options = out.options;
    options.mesh_deviation = mesh_deviation;  // the header states the bound it makes part of
    try {
      return write_cnb(s, options).size();
    } catch (const std::invalid_argument&) {
      return std::numeric_limits<size_t>::max();
    }
  };
  out.scene =
      mesh_where_cheaper ? cheapest_coding(scene, {max_deviation, kMeshShare}, coded_bytes, &out.choice, exact) : scene;
  out.options.mesh_deviation = out.choice.certified_deviation;
  out.bytes = write_cnb(out.scene, out.options, &out.written);
  if (!mesh_where_cheaper)
    out.choice.as_is_bytes = out.choice.per_body_bytes = out.choice.all_meshed_bytes = out.bytes.size();
  return out;
}

std::string meshed_bodies_basis(const CodingChoiceReport& choice) {
  if (choice.bodies_meshed == 0) return "";
  return "; it includes the certificate " + number_text(choice.certified_deviation, 4) + " of the " +
         std::to_string(choice.bodies_meshed) + " bodies (" + std::to_string(choice.faces_meshed) + " faces, " +
         std::to_string(choice.polygons_meshed) + " polygons) written as meshes";
}

}  // namespace cadnurbs
