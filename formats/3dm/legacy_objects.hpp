#pragma once
// The objects and layers of a version 1 file (Rhino 1), which has no tables: its body is a run of
// top-level chunks in any order, among them one chunk per layer and one per object (facts from
// openNURBS's Read3dmV1Layer, Read3dmV1Object and Read3dmV1AttributesOrMaterial).
//
// An object chunk holds its attribute chunks (TCODE_LAYERREF: the value is the layer's index in the
// order the layer chunks come; TCODE_NAME: int32 length and that many bytes; colours and materials,
// which openNURBS does not make the object's colour) and then the one chunk with its data:
//   TCODE_LEGACY_SHL -> shell stuff, an ON_Brep (legacy_brep.hpp)
//   TCODE_LEGACY_FAC -> face stuff, a one-face ON_Brep
//   TCODE_LEGACY_CRV -> curve stuff, a curve (legacy_nurbs.hpp)
//   TCODE_MESH_OBJECT -> TCODE_COMPRESSED_MESH_GEOMETRY, a mesh (legacy_mesh.hpp); its attributes follow it
// Points (TCODE_RH_POINT) and annotations are objects cadnurbs does not read.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "formats/3dm/archive_reader.hpp"
#include "formats/3dm/rhino_file.hpp"

namespace cadnurbs::rhino {

// The class a V1 object chunk reads as ("ON_Brep", "ON_NurbsCurve", "ON_Mesh", "V1 point", ...), or "" when
// `typecode` is not an object chunk.
std::string v1_object_class(std::uint32_t typecode);

// Reads the object chunk `h` (a top-level chunk of `bytes`, v1_object_class(h.typecode) not empty) with a
// reader of its own, so that a broken object leaves the caller's reader where it was. An object that
// cannot be read, or of a class cadnurbs does not read, comes back as Unsupported with a warning
// ("object 3 (ON_Brep): <reason>; skipped"); its attributes are kept when they could be read.
ObjectRecord read_v1_object(std::string_view bytes, const std::string& name_for_errors, const ChunkHeader& h, int index,
                            std::vector<std::string>& warnings);

// A TCODE_LAYER chunk (the reader inside it): TCODE_LAYERNAME (int32 length, bytes) and TCODE_RGB
// (value 0x00BBGGRR) among its chunks, up to TCODE_ENDOFTABLE or the chunk's end. Throws ArchiveError
// on a chunk that runs past it.
Layer read_v1_layer(ArchiveReader& reader);

}  // namespace cadnurbs::rhino
