#include "report/storage_record.hpp"

namespace cadnurbs {

const RepresentationFigures* find_representation(const PartRecord& record, const std::string& key) {
  for (const auto& r : record.representations)
    if (r.key == key) return &r;
  return nullptr;
}

const char* representation_kind_name(RepresentationKind kind) {
  switch (kind) {
    case RepresentationKind::nurbs: return "nurbs";
    case RepresentationKind::mesh: return "mesh";
    case RepresentationKind::nurss: return "nurss";
    case RepresentationKind::loop: return "loop";
  }
  return "";
}

const char* deviation_kind_name(DeviationKind kind) {
  return kind == DeviationKind::bound ? "bound" : "measured";
}

const RepresentationFigures* smallest_representation(const PartRecord& record, RepresentationKind kind) {
  const RepresentationFigures* best = nullptr;
  for (const auto& r : record.representations)
    if (r.kind == kind && (!best || delivered_bytes(r) < delivered_bytes(*best))) best = &r;
  return best;
}

}  // namespace cadnurbs
