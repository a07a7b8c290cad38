#pragma once
// The part record's JSON (schema: docs/report.md) described once per struct: each field as its key, how its
// value is written and how it is read back, in the order written (key order is part of the file's bytes).
// In: a struct and its description; out: its JSON object (report_formats writes records so), or, from such
// an object, the struct (part_record_from_json and batch_record read them so). A field is named only here.
#include <cmath>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "report/storage_record.hpp"

namespace cadnurbs {

using WrittenJson = nlohmann::ordered_json;  // keeps the keys in the order they are added
using ReadJson = nlohmann::json;

// One key of a struct's JSON object.
template <class Struct>
struct JsonField {
  const char* key;
  std::function<WrittenJson(const Struct&)> write;
  std::function<void(const ReadJson& value, Struct&)> read;  // empty for a derived figure: written, not read
};

template <class Struct>
using JsonFields = std::vector<JsonField<Struct>>;

// Adds the fields of `s` to `object`, in order.
template <class Struct>
void write_json_fields(const JsonFields<Struct>& fields, const Struct& s, WrittenJson& object) {
  for (const auto& field : fields) object[field.key] = field.write(s);
}

template <class Struct>
WrittenJson json_object(const JsonFields<Struct>& fields, const Struct& s) {
  WrittenJson object = WrittenJson::object();
  write_json_fields(fields, s, object);
  return object;
}

// Sets the fields of `s` from `object`, in order, so that the first missing key or mistyped value is the one
// reported: throws nlohmann's exceptions (or std::invalid_argument for an unknown name).
template <class Struct>
void read_json_fields(const JsonFields<Struct>& fields, const ReadJson& object, Struct& s) {
  for (const auto& field : fields)
    if (field.read) field.read(object.at(field.key), s);
}

// A member as nlohmann writes and reads its type: string, integer, double, bool, list of strings.
template <class Struct, class Value>
JsonField<Struct> value_field(const char* key, Value Struct::*member) {
  return {key, [member](const Struct& s) { return WrittenJson(s.*member); },
          [member](const ReadJson& value, Struct& s) { s.*member = value.get<Value>(); }};
}

// A double that is NaN where nothing was measured: null in the JSON.
template <class Struct>
JsonField<Struct> nullable_number_field(const char* key, double Struct::*member) {
  return {key,
          [member](const Struct& s) { return std::isnan(s.*member) ? WrittenJson(nullptr) : WrittenJson(s.*member); },
          [member](const ReadJson& value, Struct& s) {
            s.*member = value.is_null() ? std::numeric_limits<double>::quiet_NaN() : value.get<double>();
          }};
}

// A figure computed from the others (NurbsStorage::total_floats): written for readers of the file, not read.
template <class Struct, class Value>
JsonField<Struct> derived_field(const char* key, Value (Struct::*figure)() const) {
  return {key, [figure](const Struct& s) { return WrittenJson((s.*figure)()); }, nullptr};
}

// Fields of `Struct` written together as one nested object under `key`.
template <class Struct>
JsonField<Struct> group_field(const char* key, JsonFields<Struct> fields) {
  return {key, [fields](const Struct& s) { return json_object(fields, s); },
          [fields](const ReadJson& value, Struct& s) { read_json_fields(fields, value, s); }};
}

// The fields of a member struct as fields of the struct that holds it.
template <class Struct, class Member>
JsonFields<Struct> member_fields(Member Struct::*member, const JsonFields<Member>& fields) {
  JsonFields<Struct> lifted;
  for (const auto& field : fields) {
    std::function<void(const ReadJson&, Struct&)> read;
    if (field.read)
      read = [member, read_member = field.read](const ReadJson& value, Struct& s) { read_member(value, s.*member); };
    lifted.push_back(
        {field.key, [member, write_member = field.write](const Struct& s) { return write_member(s.*member); },
         std::move(read)});
  }
  return lifted;
}

// A member struct as a nested object.
template <class Struct, class Member>
JsonField<Struct> object_field(const char* key, Member Struct::*member, const JsonFields<Member>& fields) {
  return group_field(key, member_fields(member, fields));
}

// A list of structs as an array of objects; read back, each element of the value (an array's items, an
// object's values; none for null) is read as one.
template <class Struct, class Element>
JsonField<Struct> list_field(const char* key, std::vector<Element> Struct::*member, JsonFields<Element> fields) {
  return {key,
          [member, fields](const Struct& s) {
            WrittenJson list = WrittenJson::array();
            for (const auto& element : s.*member) list.push_back(json_object(fields, element));
            return list;
          },
          [member, fields](const ReadJson& value, Struct& s) {
            for (const ReadJson& item : value) {
              Element element;
              read_json_fields(fields, item, element);
              (s.*member).push_back(std::move(element));
            }
          }};
}

// The kind whose representation_kind_name is `name`; throws std::invalid_argument for another name.
inline RepresentationKind representation_kind_named(const std::string& name) {
  for (const auto kind : {RepresentationKind::nurbs, RepresentationKind::mesh, RepresentationKind::nurss,
                          RepresentationKind::loop})
    if (name == representation_kind_name(kind)) return kind;
  throw std::invalid_argument("unknown representation kind '" + name + "'");
}

// The kind whose deviation_kind_name is `name`; throws std::invalid_argument for another name.
inline DeviationKind deviation_kind_named(const std::string& name) {
  for (const auto kind : {DeviationKind::bound, DeviationKind::measured})
    if (name == deviation_kind_name(kind)) return kind;
  throw std::invalid_argument("unknown deviation kind '" + name + "'");
}

// The descriptions. Function-local statics: built once, on first use.

inline const JsonFields<NurbsStorage>& nurbs_storage_fields() {
  static const JsonFields<NurbsStorage> fields{
      value_field("surfaces", &NurbsStorage::surfaces),
      value_field("control_points", &NurbsStorage::control_points),
      value_field("knots", &NurbsStorage::knots),
      value_field("floats", &NurbsStorage::floats),
      value_field("trim_curves", &NurbsStorage::trim_curves),
      value_field("trim_control_points", &NurbsStorage::trim_control_points),
      value_field("trim_knots", &NurbsStorage::trim_knots),
      value_field("trim_polyline_points", &NurbsStorage::trim_polyline_points),
      value_field("trim_floats", &NurbsStorage::trim_floats),
      value_field("polygon_vertices", &NurbsStorage::polygon_vertices),
      value_field("polygon_corners", &NurbsStorage::polygon_corners),
      value_field("polygon_floats", &NurbsStorage::polygon_floats),
      derived_field("total_floats", &NurbsStorage::total_floats),
  };
  return fields;
}

inline const JsonFields<MeshStorage>& mesh_storage_fields() {
  static const JsonFields<MeshStorage> fields{
      value_field("vertices", &MeshStorage::vertices),
      value_field("triangles", &MeshStorage::triangles),
      value_field("indexed_floats", &MeshStorage::indexed_floats),
      value_field("indexed_integers", &MeshStorage::indexed_integers),
      value_field("indexed_floats_with_normals", &MeshStorage::indexed_floats_with_normals),
      value_field("soup_floats", &MeshStorage::soup_floats),
      value_field("soup_floats_with_normals", &MeshStorage::soup_floats_with_normals),
  };
  return fields;
}

inline const JsonFields<RepresentationFigures>& representation_fields() {
  using Figures = RepresentationFigures;
  static const JsonFields<Figures> fields{
      value_field("key", &Figures::key),
      value_field("label", &Figures::label),
      {"kind", [](const Figures& f) { return WrittenJson(representation_kind_name(f.kind)); },
       [](const ReadJson& value, Figures& f) { f.kind = representation_kind_named(value.get<std::string>()); }},
      value_field("bytes", &Figures::bytes),
      value_field("gzip_bytes", &Figures::gzip_bytes),
      value_field("floats", &Figures::floats),
      value_field("integers", &Figures::integers),
      nullable_number_field("deviation", &Figures::deviation),
      {"deviation_kind", [](const Figures& f) { return WrittenJson(deviation_kind_name(f.deviation_kind)); },
       [](const ReadJson& value, Figures& f) { f.deviation_kind = deviation_kind_named(value.get<std::string>()); }},
      value_field("deviation_basis", &Figures::deviation_basis),
  };
  return fields;
}

inline const JsonFields<StoragePoint>& storage_point_fields() {
  static const JsonFields<StoragePoint> fields{
      value_field("key", &StoragePoint::key),
      value_field("deviation", &StoragePoint::deviation),
      value_field("bytes", &StoragePoint::bytes),
      value_field("gzip_bytes", &StoragePoint::gzip_bytes),
      value_field("floats", &StoragePoint::floats),
  };
  return fields;
}

inline const JsonFields<CrossoverFigure>& crossover_fields() {
  static const JsonFields<CrossoverFigure> fields{
      value_field("mesh_key", &CrossoverFigure::mesh_key),
      value_field("nurbs_key", &CrossoverFigure::nurbs_key),
      value_field("nurbs_bytes", &CrossoverFigure::nurbs_bytes),
      nullable_number_field("deviation", &CrossoverFigure::deviation),
      value_field("mesh_larger_everywhere", &CrossoverFigure::mesh_larger_everywhere),
  };
  return fields;
}

// Every record begins with these: the input and whether it failed ("ok" or "failed"; read back, anything
// but "ok" is a failure).
inline const JsonFields<PartRecord>& part_status_fields() {
  static const JsonFields<PartRecord> fields{
      value_field("input", &PartRecord::input),
      {"status", [](const PartRecord& r) { return WrittenJson(r.failed ? "failed" : "ok"); },
       [](const ReadJson& value, PartRecord& r) { r.failed = value.get<std::string>() != "ok"; }},
  };
  return fields;
}

// What follows the status: a failed part's error alone, or a measured part's figures (and no error).
inline const JsonFields<PartRecord>& part_outcome_fields(const PartRecord& record) {
  static const JsonFields<PartRecord> failed{value_field("error", &PartRecord::error)};
  static const JsonFields<PartRecord> measured = [] {
    // The "mesh" object holds the mesh's figures and, after them, the tessellator's bound for it.
    JsonFields<PartRecord> mesh = member_fields(&PartRecord::mesh, mesh_storage_fields());
    mesh.push_back(value_field("certified_deviation", &PartRecord::mesh_certified_deviation));
    return JsonFields<PartRecord>{
        value_field("unit", &PartRecord::unit),
        value_field("diagonal", &PartRecord::diagonal),
        value_field("deviation", &PartRecord::deviation),
        object_field("nurbs", &PartRecord::nurbs, nurbs_storage_fields()),
        object_field("compact_nurbs", &PartRecord::compact_nurbs, nurbs_storage_fields()),
        group_field("mesh", std::move(mesh)),
        list_field("representations", &PartRecord::representations, representation_fields()),
        list_field("curve", &PartRecord::curve, storage_point_fields()),
        list_field("crossovers", &PartRecord::crossovers, crossover_fields()),
        value_field("warnings", &PartRecord::warnings),
    };
  }();
  return record.failed ? failed : measured;
}

}  // namespace cadnurbs
