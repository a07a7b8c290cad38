#include "converters/cnb_coding.hpp"

#include "core/number_format.hpp"
#include "formats/cnb/cnb_writer.hpp"

namespace cadnurbs {

namespace {
// The share of D that trims (in (u,v)) and meshes (their certificate) may use; points get the rest.
constexpr double kMeshShare = 0.4;
}  // namespace

CnbCoding cnb_coding(const Scene& scene, double max_deviation) {
  CnbCoding out;
  out.options.max_deviation = max_deviation;
  out.options.trim_share = kMeshShare;
  // The bytes do not depend on mesh_deviation (it only joins the stated bound), so candidates are costed
  // without it.
  const CnbOptions costing = out.options;
  out.scene = cheapest_coding(
      scene, {max_deviation, kMeshShare}, [&](const Scene& s) { return write_cnb(s, costing).size(); }, &out.choice);
  out.options.mesh_deviation = out.choice.certified_deviation;
  out.bytes = write_cnb(out.scene, out.options, &out.written);
  return out;
}

std::string meshed_bodies_basis(const CodingChoiceReport& choice) {
  if (choice.bodies_meshed == 0) return "";
  return "; it includes the certificate " + number_text(choice.certified_deviation, 4) + " of the " +
         std::to_string(choice.bodies_meshed) + " bodies (" + std::to_string(choice.faces_meshed) + " faces, " +
         std::to_string(choice.polygons_meshed) + " polygons) written as meshes";
}

}  // namespace cadnurbs
