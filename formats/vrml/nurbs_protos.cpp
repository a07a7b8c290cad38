#include "formats/vrml/nurbs_protos.hpp"

#include <stdexcept>

namespace cadnurbs {

const std::vector<ProtoDefinition>& nurbs_protos() {
  static const std::vector<ProtoDefinition> protos = [] {
    try {
      return parse_proto_library(nurbs_protos_library());
    } catch (const std::runtime_error& e) {
      throw std::runtime_error("cadnurbs-nurbs-protos.wrl: " + std::string(e.what()));
    }
  }();
  return protos;
}

}  // namespace cadnurbs
