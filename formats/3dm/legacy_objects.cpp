#include "formats/3dm/legacy_objects.hpp"

#include <array>

#include "formats/3dm/legacy_brep.hpp"
#include "formats/3dm/legacy_mesh.hpp"
#include "formats/3dm/legacy_nurbs.hpp"
#include "formats/3dm/typecodes.hpp"

namespace cadnurbs::rhino {

namespace {

// The data of a V1 object once its stuff chunk is open.
using ReadStuff = RhinoGeometry (*)(ArchiveReader&);

struct V1ObjectKind {
  std::uint32_t typecode;
  const char* class_name;
  std::uint32_t stuff;  // 0: cadnurbs does not read the class
  ReadStuff read;
};

constexpr std::array<V1ObjectKind, 10> kKinds = {{
    {tcode::kLegacyShell, "ON_Brep", tcode::kLegacyShellStuff,
     [](ArchiveReader& r) -> RhinoGeometry { return read_legacy_shell(r); }},
    {tcode::kLegacyFace, "ON_Brep", tcode::kLegacyFaceStuff,
     [](ArchiveReader& r) -> RhinoGeometry { return read_legacy_face(r); }},
    {tcode::kLegacyCurve, "ON_NurbsCurve", tcode::kLegacyCurveStuff,
     [](ArchiveReader& r) -> RhinoGeometry { return read_legacy_curve(r); }},
    {tcode::kMeshObject, "ON_Mesh", tcode::kCompressedMeshGeometry,
     [](ArchiveReader& r) -> RhinoGeometry { return read_legacy_mesh(r); }},
    {tcode::kRhPoint, "V1 point", 0, nullptr},
    {tcode::kAnnotation | 0x0004u, "V1 text block", 0, nullptr},
    {tcode::kAnnotation | 0x0005u, "V1 leader", 0, nullptr},
    {tcode::kAnnotation | 0x0006u, "V1 linear dimension", 0, nullptr},
    {tcode::kAnnotation | 0x0007u, "V1 angular dimension", 0, nullptr},
    {tcode::kAnnotation | 0x0008u, "V1 radial dimension", 0, nullptr},
}};

const V1ObjectKind* kind_of(std::uint32_t typecode) {
  for (const auto& kind : kKinds)
    if (kind.typecode == typecode) return &kind;
  return nullptr;
}

// A V1 string: int32 length, then that many bytes (trailing zero bytes dropped).
std::string v1_string(ArchiveReader& reader) {
  std::string s(reader.raw(reader.count(1)));
  while (!s.empty() && s.back() == '\0') s.pop_back();
  return s;
}

}  // namespace

std::string v1_object_class(std::uint32_t typecode) {
  const V1ObjectKind* kind = kind_of(typecode);
  return kind ? kind->class_name : "";
}

ObjectRecord read_v1_object(std::string_view bytes, const std::string& name_for_errors, const ChunkHeader& h, int index,
                            std::vector<std::string>& warnings) {
  ObjectRecord out;
  out.index = index;
  out.class_name = v1_object_class(h.typecode);
  out.geometry = Unsupported{out.class_name};
  const std::string where = "object " + std::to_string(index) + " (" + out.class_name + ")";
  const V1ObjectKind* kind = kind_of(h.typecode);
  if (!kind || !kind->read) {
    warnings.push_back(where + ": not supported, skipped");
    return out;
  }
  ArchiveReader reader(bytes, name_for_errors, 1, h.offset);
  try {
    reader.begin_chunk(h.typecode);
    // Attributes come before the data chunk (shells, faces, curves) or after it (meshes).
    bool read = false;
    while (reader.bytes_left() >= 8) {
      const ChunkHeader a = reader.begin_chunk();
      if (a.typecode == tcode::kEndOfTable) break;
      if (!read && a.typecode == kind->stuff && !a.is_short()) {
        out.geometry = kind->read(reader);
        read = true;
      } else if (a.typecode == tcode::kLayerRef) {
        out.attributes.layer_index = static_cast<int>(a.value);
      } else if (a.typecode == tcode::kName) {
        out.attributes.name = v1_string(reader);
      }
      if (!a.is_short()) reader.end_chunk();
    }
    if (!read) reader.fail(std::string("no ") + out.class_name + " data chunk");
  } catch (const ArchiveError& e) {
    warnings.push_back(where + ": " + e.what() + "; skipped");
    out.geometry = Unsupported{out.class_name};
  }
  return out;
}

Layer read_v1_layer(ArchiveReader& reader) {
  Layer layer;
  while (reader.bytes_left() >= 8) {
    const ChunkHeader h = reader.begin_chunk();
    if (h.typecode == tcode::kEndOfTable) break;
    if (h.typecode == tcode::kRgb) {
      const auto rgb = static_cast<std::uint32_t>(h.value);
      layer.colour = Colour{(rgb & 0xFFu) / 255.0, ((rgb >> 8) & 0xFFu) / 255.0, ((rgb >> 16) & 0xFFu) / 255.0};
    } else if (h.typecode == tcode::kV1LayerName) {
      layer.name = v1_string(reader);
    }
    if (!h.is_short()) reader.end_chunk();
  }
  return layer;
}

}  // namespace cadnurbs::rhino
