#pragma once
// An exact binary serialisation of a Scene, for handing a scene from one process to another (the
// STEP/IGES reader's child process to the command, converters/walled_read). Every field goes through:
// the node tree, names, source entities and types, transforms (all 16 matrix entries), colours, shapes of
// each geometry kind with their trimming loops and TrimEdgeRefs, both units. Doubles are their IEEE bits,
// so what is read back is bit-identical to what was written.
//
// Layout: an 8-byte magic ("CNSCENE\0", or "CNBREPT\0" for a BrepTranslation), a u32 version (1), then the
// content; integers little-endian (u8, i32, u64 counts), doubles as little-endian u64 bits, a string as a
// u64 length and its bytes, an optional as a u8 0/1 and the value, a geometry as a u8 kind (0 trimmed
// surface, 1 curve, 2 triangle mesh, 3 polygon mesh) and its fields in declaration order.
#include <string>
#include <string_view>

#include "core/scene.hpp"
#include "formats/brep/brep_translation.hpp"

namespace cadnurbs {

// The bytes of `scene`.
std::string write_scene_stream(const Scene& scene);

// The scene `bytes` hold. Refuses (FileError, one line "<name_for_errors>: scene stream ...") input that
// write_scene_stream did not make: a wrong magic or version; a stream that ends early (the field and byte
// offset are named); a count larger than the bytes left could hold (checked before anything is
// allocated); an unknown geometry kind; a flag other than 0 or 1; nodes nested deeper than 10,000; bytes
// after the end. What it reads is not validated as geometry (validate(scene) does that).
Scene read_scene_stream(std::string_view bytes, const std::string& name_for_errors);

// The same for a B-rep reader's result: its scene, then fallbacks, repairs, face_count and
// degenerated_edges.
std::string write_translation_stream(const BrepTranslation& translation);
BrepTranslation read_translation_stream(std::string_view bytes, const std::string& name_for_errors);

}  // namespace cadnurbs
