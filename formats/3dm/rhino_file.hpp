#pragma once
// A whole .3dm file: start section and version, unit system and tolerance, layers, and the object table's
// objects converted by read_object, with their names, layers and colours. Version 1 files (Rhino 1's
// legacy layout, no tables) give their layers, units and legacy objects (legacy_objects.hpp) the same way.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/scene.hpp"
#include "formats/3dm/rhino_object.hpp"

namespace cadnurbs::rhino {

struct Layer {
  std::string name;
  Colour colour;  // the layer's display colour, 0..1
};

struct ObjectAttributes {
  std::string name;
  int layer_index = -1;           // into Rhino3dmFile::layers; may be -1 or out of range in odd files
  std::optional<Colour> colour;   // set only when the object's colour source is "from object"
};

struct ObjectRecord {
  int index = 0;  // 0-based position in the object table
  std::string class_name;  // openNURBS's class ("ON_Brep"; legacy ids by the class they read as), or the id
  // Unsupported (with the class name) when cadnurbs does not convert the class or its data could not be
  // read; a warning then says which.
  RhinoGeometry geometry;
  ObjectAttributes attributes;
};

struct Rhino3dmFile {
  int archive_version = 0;  // 1..5, 50, 60, 70, 80
  LengthUnit unit;          // the model's unit; none or unknown -> mm with a warning
  double absolute_tolerance = 0;
  std::vector<Layer> layers;
  std::vector<ObjectRecord> objects;  // every object record, in file order
  std::vector<std::string> warnings;  // e.g. "object 3 (ON_SubD): not supported, skipped"
};

// Parses a whole file held in memory. Throws ArchiveError (one line naming chunk typecode and offset) on a
// truncated or corrupt chunk structure, and on a start section that is not "3D Geometry File Format "
// followed by one of the versions above. An object whose data cannot be read is skipped with a warning
// naming its index and class; reading goes on with the next record.
Rhino3dmFile parse_3dm(std::string_view bytes, const std::string& name_for_errors);

// read_file(path) then parse_3dm; a file that cannot be opened throws FileError.
Rhino3dmFile read_3dm_file(const std::string& path);

}  // namespace cadnurbs::rhino
