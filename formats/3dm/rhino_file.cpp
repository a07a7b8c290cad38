#include "formats/3dm/rhino_file.hpp"

#include <array>
#include <cstring>

#include "formats/3dm/legacy_objects.hpp"
#include "formats/3dm/typecodes.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs::rhino {
namespace {

constexpr std::string_view kStart = "3D Geometry File Format ";
constexpr std::size_t kStartSize = 32;  // kStart and the version, right-aligned in 8 characters

int start_section_version(std::string_view bytes, const std::string& name) {
  if (bytes.size() < kStartSize || bytes.substr(0, kStart.size()) != kStart)
    throw ArchiveError(name + ": offset 0: not a .3dm file (no \"3D Geometry File Format\" start section)");
  std::string_view field = bytes.substr(kStart.size(), 8);
  while (!field.empty() && field.front() == ' ') field.remove_prefix(1);
  int version = 0;
  for (const char c : field) {
    if (c < '0' || c > '9' || field.size() > 3) {
      version = -1;
      break;
    }
    version = version * 10 + (c - '0');
  }
  const bool known = (version >= 1 && version <= 5) || version == 50 || version == 60 || version == 70 || version == 80;
  if (!known)
    throw ArchiveError(name + ": offset " + std::to_string(kStart.size()) + ": archive version \"" +
                       std::string(bytes.substr(kStart.size(), 8)) +
                       "\" is not one cadnurbs reads (1-5, 50, 60, 70, 80)");
  return version;
}

Colour colour_from_bytes(std::string_view rgba) {  // ON_Color on disk: red, green, blue, alpha bytes
  const auto channel = [&](int i) { return static_cast<unsigned char>(rgba[static_cast<std::size_t>(i)]) / 255.0; };
  return {channel(0), channel(1), channel(2)};
}

// ON::LengthUnitSystem codes (opennurbs_defines.h) with names and millimetres per unit.
struct RhinoUnit {
  int code;
  const char* name;
  double millimetres;
};
constexpr std::array<RhinoUnit, 24> kUnits = {{
    {1, "um", 1e-3},         {2, "mm", 1.0},          {3, "cm", 10.0},         {4, "m", 1e3},
    {5, "km", 1e6},          {6, "uin", 2.54e-5},     {7, "mil", 0.0254},      {8, "inch", 25.4},
    {9, "ft", 304.8},        {10, "mi", 1609344.0},   {12, "angstrom", 1e-7},  {13, "nm", 1e-6},
    {14, "dm", 100.0},       {15, "dam", 1e4},        {16, "hm", 1e5},         {17, "Mm", 1e9},
    {18, "Gm", 1e12},        {19, "yd", 914.4},       {20, "pt", 25.4 / 72},   {21, "pica", 25.4 / 6},
    {22, "nmi", 1852e3},     {23, "au", 1.4959787e14}, {24, "ly", 9.4607304725808e18}, {25, "pc", 3.0856775814913673e19},
}};
constexpr int kCustomUnits = 11;

// Sets file.unit to the unit of `code`; false when the table does not have it.
bool set_unit(int code, Rhino3dmFile& file) {
  for (const RhinoUnit& u : kUnits)
    if (u.code == code) {
      file.unit = LengthUnit{u.name, u.millimetres};
      return true;
    }
  return false;
}

void warn_no_unit(int code, Rhino3dmFile& file) {
  file.unit = LengthUnit{};
  file.warnings.push_back(code == 0 ? "the model has no unit system; millimetres assumed"
                                    : "unknown unit system " + std::to_string(code) + "; millimetres assumed");
}

// TCODE_SETTINGS_UNITSANDTOLS (ON_3dmUnitsAndTolerances): int version 100..199, unit code, absolute,
// angle and relative tolerance; from 101 display mode and precision; from 102 metres per unit and the
// custom unit's name.
void read_units_and_tolerances(ArchiveReader& reader, Rhino3dmFile& file) {
  const std::int32_t version = reader.i32();
  if (version < 100 || version >= 200) {
    file.warnings.push_back("units and tolerances record version " + std::to_string(version) +
                            " unknown; millimetres assumed");
    return;
  }
  const std::int32_t code = reader.i32();
  file.absolute_tolerance = reader.f64();
  reader.skip(16);  // angle and relative tolerance
  double metres_per_unit = 0;
  std::string custom_name;
  if (version >= 101) reader.skip(8);  // distance display mode and precision
  if (version >= 102) {
    metres_per_unit = reader.f64();
    custom_name = reader.wide_string();
  }
  if (set_unit(code, file)) return;
  if (code == kCustomUnits && metres_per_unit > 0) {
    file.unit = LengthUnit{custom_name.empty() ? "custom" : custom_name, metres_per_unit * 1000};
    return;
  }
  warn_no_unit(code, file);
}

// A V1 TCODE_UNIT_AND_TOLERANCES chunk: int32 version, unit code (0 none, 1..10 the codes of kUnits),
// absolute, relative and angle tolerance.
void read_v1_units_and_tolerances(ArchiveReader& reader, Rhino3dmFile& file) {
  reader.i32();
  const std::int32_t code = reader.i32();
  file.absolute_tolerance = reader.f64();
  if (code < 1 || code > 10 || !set_unit(code, file)) warn_no_unit(code, file);
}

// Calls read(header) for each record of the table the reader is in, up to its TCODE_ENDOFTABLE mark (or
// the table's end), then steps over the record by its length. `read` reads the record with a reader of its
// own (record_reader), so that a record it cannot read leaves the table's reader where it was.
template <class ReadRecord>
void for_each_record(ArchiveReader& reader, ReadRecord&& read) {
  while (reader.bytes_left() > 0) {
    const ChunkHeader h = reader.peek_chunk();  // refuses a record longer than the table
    reader.begin_chunk();
    if (h.typecode == tcode::kEndOfTable) break;
    if (h.is_short()) continue;
    read(h);
    reader.end_chunk();
  }
}

// A reader inside the record `h` of the table `table` reads.
ArchiveReader record_reader(const ArchiveReader& table, std::string_view bytes, const ChunkHeader& h) {
  ArchiveReader reader(bytes, table.name(), table.archive_version(), h.offset);
  reader.begin_chunk(h.typecode);
  return reader;
}

// The units chunk `h` read by `read` (V2+ record or V1 chunk); unreadable: millimetres, with a warning.
void read_units(const ArchiveReader& reader, std::string_view bytes, const ChunkHeader& h, Rhino3dmFile& file,
                void (*read)(ArchiveReader&, Rhino3dmFile&)) {
  try {
    ArchiveReader record = record_reader(reader, bytes, h);
    read(record, file);
  } catch (const ArchiveError& e) {
    file.unit = LengthUnit{};
    file.warnings.push_back(std::string("units and tolerances unreadable (") + e.what() + "); millimetres assumed");
  }
}

void read_settings(ArchiveReader& reader, std::string_view bytes, Rhino3dmFile& file) {
  for_each_record(reader, [&](const ChunkHeader& h) {
    if (h.typecode == tcode::kSettingsUnitsAndTolerances) read_units(reader, bytes, h, file, read_units_and_tolerances);
  });
}

// A layer record holds an ON_Layer object: its chunk version 1.x data starts with mode, index, IGES level,
// material index, an obsolete int, the colour, an obsolete line style (2 shorts, 2 doubles), the name.
Layer read_layer(ArchiveReader& reader) {
  Layer layer;
  reader.begin_chunk(tcode::kOpennurbsClass);
  reader.begin_chunk(tcode::kOpennurbsClassUuid);
  reader.uuid();
  reader.end_chunk();
  reader.begin_chunk(tcode::kOpennurbsClassData);
  const auto [major, minor] = reader.chunk_version();
  if (major != 1) reader.fail("ON_Layer: chunk version " + std::to_string(major) + "." + std::to_string(minor) + " is not 1.x");
  reader.skip(5 * 4);
  layer.colour = colour_from_bytes(reader.raw(4));
  reader.skip(2 * 2 + 2 * 8);
  layer.name = reader.wide_string();
  return layer;
}

// The layer chunk `h` read by `read` (V2+ record or V1 chunk). A layer that cannot be read keeps its place
// (objects refer to layers by position) under a made-up name.
void add_layer(const ArchiveReader& reader, std::string_view bytes, const ChunkHeader& h, Rhino3dmFile& file,
               Layer (*read)(ArchiveReader&)) {
  const std::string placeholder = "layer " + std::to_string(file.layers.size());
  try {
    ArchiveReader record = record_reader(reader, bytes, h);
    file.layers.push_back(read(record));
  } catch (const ArchiveError& e) {
    file.warnings.push_back(placeholder + ": " + e.what() + "; named \"" + placeholder + "\"");
    file.layers.push_back(Layer{placeholder, Colour{}});
  }
}

void read_layers(ArchiveReader& reader, std::string_view bytes, Rhino3dmFile& file) {
  for_each_record(reader, [&](const ChunkHeader& h) {
    if (h.typecode == tcode::kLayerRecord) add_layer(reader, bytes, h, file, read_layer);
  });
}

constexpr int kColourFromObject = 1;  // ON::object_color_source::color_from_object

// ON_3dmObjectAttributes. Chunk version 2.x (Rhino 5 on): id, layer index, then optional items each
// introduced by its number in increasing order (1 name, 2 url, 3 linetype, 4 material, 5 rendering
// chunk, 6 colour, 7 plot colour, 8 plot weight, 9 decoration, 10 wire density, 11 visible, 12 mode,
// 13 colour source, ...), 0 ending the list. Version 1.x: fixed fields in order.
ObjectAttributes read_attributes(ArchiveReader& reader) {
  ObjectAttributes out;
  const auto [major, minor] = reader.chunk_version();
  std::optional<Colour> colour;
  int colour_source = 0;
  if (major == 2) {
    reader.uuid();
    out.layer_index = reader.i32();
    for (std::uint8_t item = reader.u8(); item != 0 && item <= 13; item = reader.u8()) {
      switch (item) {
        case 1: out.name = reader.wide_string(); break;
        case 2: reader.wide_string(); break;
        case 3: case 4: case 10: reader.skip(4); break;
        case 5: reader.begin_chunk(tcode::kAnonymousChunk); reader.end_chunk(); break;
        case 6: colour = colour_from_bytes(reader.raw(4)); break;
        case 7: reader.skip(4); break;
        case 8: reader.skip(8); break;
        case 9: case 11: case 12: reader.skip(1); break;
        case 13: colour_source = reader.u8(); break;
        default: break;
      }
      if (item == 13) break;  // nothing after the colour source is needed
    }
  } else if (major == 1) {
    reader.uuid();
    out.layer_index = reader.i32();
    reader.skip(4);  // material index
    colour = colour_from_bytes(reader.raw(4));
    reader.skip(2 * 2 + 2 * 8 + 4 + 1);  // obsolete line style, wire density, mode
    colour_source = reader.u8();
    reader.skip(2);  // linetype and material sources
    out.name = reader.wide_string();
  } else {
    reader.fail("ON_3dmObjectAttributes: chunk version " + std::to_string(major) + "." + std::to_string(minor) +
                " is not 1.x or 2.x");
  }
  if (colour_source == kColourFromObject) out.colour = colour.value_or(Colour{0, 0, 0});
  return out;
}

// The class name of the object at `offset` (a TCODE_OPENNURBS_CLASS chunk), for messages.
std::string class_at(std::string_view bytes, const std::string& name, int version, std::size_t offset) {
  try {
    ArchiveReader reader(bytes, name, version, offset);
    reader.begin_chunk(tcode::kOpennurbsClass);
    reader.begin_chunk(tcode::kOpennurbsClassUuid);
    const Uuid id = reader.uuid();
    const std::string known = class_name(id);
    return known.empty() ? id.text() : known;
  } catch (const ArchiveError&) {
    return "unreadable class";
  }
}

// One TCODE_OBJECT_RECORD (see for_each_record): the record type, the object, then its attributes and
// other chunks up to the end mark.
ObjectRecord read_object_record(const ArchiveReader& table, std::string_view bytes, const ChunkHeader& h, int index,
                                std::vector<std::string>& warnings) {
  ObjectRecord out;
  out.index = index;
  out.geometry = Unsupported{"unreadable class"};
  const std::string where = "object " + std::to_string(index);
  std::string klass = "no object";
  ArchiveReader reader = record_reader(table, bytes, h);
  try {
    reader.begin_chunk(tcode::kObjectRecordType);
    klass = out.class_name = class_at(bytes, table.name(), table.archive_version(), reader.offset());
    out.geometry = read_object(reader);
  } catch (const ArchiveError& e) {
    warnings.push_back(where + " (" + klass + "): " + e.what() + "; skipped");
    out.geometry = Unsupported{klass};
    return out;
  }
  if (const auto* u = std::get_if<Unsupported>(&out.geometry))
    warnings.push_back(where + " (" + u->class_name + "): not supported, skipped");
  try {
    while (reader.bytes_left() > 0) {
      const ChunkHeader h = reader.begin_chunk();
      if (h.typecode == tcode::kObjectRecordEnd) break;
      if (h.is_short()) continue;
      if (h.typecode == tcode::kObjectRecordAttributes) out.attributes = read_attributes(reader);
      reader.end_chunk();
    }
  } catch (const ArchiveError& e) {
    warnings.push_back(where + " (" + klass + "): attributes unreadable (" + e.what() + "); default layer and colour");
    out.attributes = {};
  }
  return out;
}

void read_objects(ArchiveReader& reader, std::string_view bytes, Rhino3dmFile& file) {
  int index = 0;
  for_each_record(reader, [&](const ChunkHeader& h) {
    if (h.typecode == tcode::kObjectRecord) file.objects.push_back(read_object_record(reader, bytes, h, index++, file.warnings));
  });
}

// A version 1 body: top-level chunks in any order (no tables); layers, units and objects are read where
// they are, everything else is stepped over by its length. A layer or the units that cannot be read are
// replaced as in later versions, with a warning.
void parse_v1(std::string_view bytes, const std::string& name, Rhino3dmFile& file) {
  ArchiveReader reader(bytes, name, 1, kStartSize);
  reader.begin_chunk(tcode::kCommentBlock);
  reader.end_chunk();
  bool units_seen = false;
  int index = 0;
  while (reader.bytes_left() > 0) {
    const ChunkHeader h = reader.begin_chunk();
    if (h.is_short()) continue;
    if (!v1_object_class(h.typecode).empty()) {
      file.objects.push_back(read_v1_object(bytes, name, h, index++, file.warnings));
    } else if (h.typecode == tcode::kUnitAndTolerances) {
      units_seen = true;
      read_units(reader, bytes, h, file, read_v1_units_and_tolerances);
    } else if (h.typecode == tcode::kV1Layer) {
      add_layer(reader, bytes, h, file, read_v1_layer);
    }
    reader.end_chunk();
    if (h.typecode == tcode::kEndOfFile) break;
  }
  if (!units_seen) file.warnings.push_back("no units and tolerances chunk; millimetres assumed");
}

}  // namespace

Rhino3dmFile parse_3dm(std::string_view bytes, const std::string& name_for_errors) {
  Rhino3dmFile file;
  file.archive_version = start_section_version(bytes, name_for_errors);
  if (file.archive_version == 1) {
    parse_v1(bytes, name_for_errors, file);
    return file;
  }
  ArchiveReader reader(bytes, name_for_errors, file.archive_version, kStartSize);
  reader.begin_chunk(tcode::kCommentBlock);
  reader.end_chunk();
  bool units_seen = false;
  while (reader.bytes_left() > 0) {
    const ChunkHeader h = reader.begin_chunk();
    if (h.is_short()) continue;
    switch (h.typecode) {
      case tcode::kSettingsTable: read_settings(reader, bytes, file); units_seen = true; break;
      case tcode::kLayerTable: read_layers(reader, bytes, file); break;
      case tcode::kObjectTable: read_objects(reader, bytes, file); break;
      default: break;  // tables cadnurbs does not need are stepped over by their length
    }
    reader.end_chunk();
    if (h.typecode == tcode::kEndOfFile) break;
  }
  if (!units_seen) file.warnings.push_back("no settings table; millimetres assumed");
  return file;
}

Rhino3dmFile read_3dm_file(const std::string& path) {
  const std::string bytes = read_file(path);
  return parse_3dm(bytes, path);
}

}  // namespace cadnurbs::rhino
