#pragma once
// Test helpers for the class readers: finding the objects of one class in a corpus .3dm file by scanning
// its bytes for the class id inside a TCODE_OPENNURBS_CLASS_UUID chunk (also the objects nested in Breps,
// polycurves and revolutions) and opening a reader at the class data, so that a class reader can be
// tested on real files independently of the table and Brep readers; hand-built class data and objects,
// and the message they are refused with.
#include <cstring>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include <zlib.h>

#include "core/nurbs_curve.hpp"
#include "formats/3dm/archive_reader.hpp"
#include "formats/3dm/typecodes.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs::rhino::testing {

// The archive version from the start section "3D Geometry File Format        N".
inline int archive_version_of(const std::string& bytes) {
  if (bytes.size() < 32 || bytes.compare(0, 24, "3D Geometry File Format ") != 0)
    throw std::runtime_error("not a .3dm file");
  return std::stoi(bytes.substr(24, 8));
}

// Offsets of the TCODE_OPENNURBS_CLASS chunks whose class id is `class_id`, in file order.
inline std::vector<std::size_t> class_chunk_offsets(const std::string& bytes, const std::string& class_id) {
  const int version = archive_version_of(bytes);
  const std::size_t header = 4 + (version >= 50 ? 8 : 4);
  const Uuid id = uuid_from_text(class_id);
  const std::string needle(reinterpret_cast<const char*>(id.bytes.data()), id.bytes.size());
  auto typecode_at = [&](std::size_t at) {
    std::uint32_t t = 0;
    std::memcpy(&t, bytes.data() + at, 4);
    return t;
  };
  std::vector<std::size_t> out;
  for (std::size_t at = bytes.find(needle); at != std::string::npos; at = bytes.find(needle, at + 1)) {
    if (at < 2 * header) continue;
    const std::size_t object = at - 2 * header;
    if (typecode_at(at - header) == tcode::kOpennurbsClassUuid && typecode_at(object) == tcode::kOpennurbsClass)
      out.push_back(object);
  }
  return out;
}

// A reader inside the class data chunk of the object at `offset` (from class_chunk_offsets).
inline ArchiveReader reader_at_class_data(const std::string& bytes, const std::string& name, std::size_t offset) {
  ArchiveReader reader(bytes, name, archive_version_of(bytes), offset);
  reader.begin_chunk(tcode::kOpennurbsClass);
  reader.begin_chunk(tcode::kOpennurbsClassUuid);
  reader.end_chunk();
  reader.begin_chunk(tcode::kOpennurbsClassData);
  return reader;
}

inline std::string corpus_file(const char* name) {
  return read_file(std::string(CADNURBS_SHARED_DIR "/corpus/3dm/") + name);
}

// Class data built by hand, little-endian; chunk() frames it in a TCODE_OPENNURBS_CLASS chunk of an
// archive version 50+ file (8-byte length, no CRC), so that messages name that chunk at offset 0.
struct ClassData {
  std::string body;
  template <class T>
  ClassData& put(T value) {
    char b[sizeof value];
    std::memcpy(b, &value, sizeof value);
    body.append(b, sizeof value);
    return *this;
  }
  ClassData& doubles(std::initializer_list<double> values) {
    for (double v : values) put(v);
    return *this;
  }
  std::string chunk() const {
    ClassData c;
    c.put(tcode::kOpennurbsClass).put(static_cast<std::int64_t>(body.size()));
    return c.body + body;
  }
};

// what() of the ArchiveError that `read` throws on ClassData::chunk() bytes, or "no error".
template <class Read>
std::string error_of(const std::string& bytes, Read read) {
  ArchiveReader reader(bytes, "hand.3dm", 70);
  reader.begin_chunk();
  try {
    read(reader);
  } catch (const ArchiveError& e) {
    return e.what();
  }
  return "no error";
}

// An object as WriteObject frames it: class chunk, class id (with its CRC), class data (with its CRC),
// end. The data is the class's own bytes, then `nested` objects, which a chunk's CRC leaves out.
inline std::string object_chunk(const char* class_id, const std::string& own, const std::string& nested = "") {
  auto with_crc = [](std::uint32_t typecode, const std::string& body, const std::string& after) {
    ClassData c;
    c.put(typecode).put(static_cast<std::int64_t>(body.size() + after.size() + 4));
    c.body += body + after;
    c.put(static_cast<std::uint32_t>(::crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()))));
    return c.body;
  };
  const Uuid id = uuid_from_text(class_id);
  const std::string uuid(reinterpret_cast<const char*>(id.bytes.data()), id.bytes.size());
  ClassData end;
  end.put(tcode::kOpennurbsClassEnd).put(std::int64_t{0});
  ClassData object;
  object.body = with_crc(tcode::kOpennurbsClassUuid, uuid, "") + with_crc(tcode::kOpennurbsClassData, own, nested) + end.body;
  return object.chunk();
}

// The straight line a -> b over [t0, t1] as an order-2 NURBS.
inline NurbsCurve line(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double t0, double t1) {
  NurbsCurve c;
  c.order = 2;
  c.knots = {t0, t0, t1, t1};
  c.points = {a, b};
  return c;
}

}  // namespace cadnurbs::rhino::testing
