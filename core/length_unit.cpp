#include "core/length_unit.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace cadnurbs {

namespace {

struct Spelling {
  const char* spelling;  // lower case
  const char* name;
  double millimetres;
};

constexpr std::array<Spelling, 37> spellings = {{
    {"mm", "mm", 1.0},           {"millimetre", "mm", 1.0},     {"millimeter", "mm", 1.0},
    {"cm", "cm", 10.0},          {"centimetre", "cm", 10.0},    {"centimeter", "cm", 10.0},
    {"m", "m", 1000.0},          {"metre", "m", 1000.0},        {"meter", "m", 1000.0},
    {"km", "km", 1e6},           {"kilometre", "km", 1e6},      {"kilometer", "km", 1e6},
    {"um", "um", 1e-3},          {"micrometre", "um", 1e-3},    {"micrometer", "um", 1e-3},
    {"micron", "um", 1e-3},      {"microns", "um", 1e-3},       {"nm", "nm", 1e-6},
    {"nanometre", "nm", 1e-6},   {"nanometer", "nm", 1e-6},     {"in", "inch", 25.4},
    {"inch", "inch", 25.4},      {"inches", "inch", 25.4},      {"ft", "ft", 304.8},
    {"foot", "ft", 304.8},       {"feet", "ft", 304.8},         {"mil", "mil", 0.0254},
    {"mils", "mil", 0.0254},     {"uin", "uin", 2.54e-5},       {"microinch", "uin", 2.54e-5},
    {"mi", "mi", 1609344.0},     {"mile", "mi", 1609344.0},     {"miles", "mi", 1609344.0},
    {"dm", "dm", 100.0},         {"decimetre", "dm", 100.0},    {"decimeter", "dm", 100.0},
    {"kicad", "kicad", 2.54},
}};

void scale_lengths(SceneNode& node, double factor) {
  node.transform.translation() *= factor;
  for (auto& shape : node.shapes) {
    if (auto* trimmed = std::get_if<TrimmedSurface>(&shape.geometry)) {
      for (auto& p : trimmed->surface.points) p *= factor;
    } else if (auto* curve = std::get_if<NurbsCurve>(&shape.geometry)) {
      for (auto& p : curve->points) p *= factor;
    } else if (auto* mesh = std::get_if<TriangleMesh>(&shape.geometry)) {
      for (auto& p : mesh->positions) p *= factor;
    }
  }
  for (auto& child : node.children) scale_lengths(child, factor);
}

}  // namespace

std::optional<LengthUnit> length_unit_named(const std::string& name) {
  std::string key;
  for (char c : name)
    if (!std::isspace(static_cast<unsigned char>(c))) key += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const auto& s : spellings)
    if (key == s.spelling) return LengthUnit{s.name, s.millimetres};
  return std::nullopt;
}

Scene in_unit(Scene scene, const LengthUnit& unit) {
  if (scene.unit.millimetres != unit.millimetres) scale_lengths(scene.root, scene.unit.millimetres / unit.millimetres);
  scene.unit = unit;
  return scene;
}

}  // namespace cadnurbs
