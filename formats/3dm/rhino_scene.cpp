#include "formats/3dm/rhino_scene.hpp"

#include <filesystem>

#include "core/geometry_error.hpp"
#include "core/length_unit.hpp"
#include "core/repair_trimming_loops.hpp"

namespace cadnurbs::rhino {

namespace {

std::string object_label(const ObjectRecord& object) {
  std::string label = "object " + std::to_string(object.index);
  if (!object.attributes.name.empty()) label += " '" + object.attributes.name + "'";
  return label;
}

// The object's node and its shapes; edge numbers of a Brep offset by the scene's running count.
SceneNode object_node(const ObjectRecord& object, RhinoScene& out) {
  SceneNode node;
  node.name = object.attributes.name;
  node.source_entity = "object " + std::to_string(object.index);
  node.colour = object.attributes.colour;
  const std::string label = object_label(object);
  std::visit(
      [&](const auto& geometry) {
        using T = std::decay_t<decltype(geometry)>;
        if constexpr (std::is_same_v<T, RhinoBrep>) {
          // A face that cannot be trimmed NURBS: Rhino's render mesh of it, or nothing.
          auto fall_back = [&](int file_index, std::string reason) {
            const int number = file_index + 1;
            // The reason without the face's own name in front ("face K: ", "object N face K: ").
            for (const std::string& prefix : {label + " face " + std::to_string(number) + ": ",
                                              "face " + std::to_string(number) + ": "})
              if (reason.rfind(prefix, 0) == 0) reason.erase(0, prefix.size());
            const auto& meshes = geometry.render_meshes;
            if (file_index < static_cast<int>(meshes.size()) && meshes[file_index]) {
              Shape shape;
              shape.source_entity = "face " + std::to_string(number) + " (mesh)";
              shape.source_type = "Brep face";
              shape.geometry = *meshes[file_index];
              node.shapes.push_back(std::move(shape));
              out.meshed_faces.push_back({label, number, reason});
              ++out.face_count;
            } else {
              out.warnings.push_back(label + " face " + std::to_string(number) + ": left out (no render mesh): " + reason);
              ++out.skipped_faces;
            }
          };
          for (size_t k = 0; k < geometry.skipped_faces.size(); ++k)
            fall_back(geometry.skipped_face_indices.at(k), geometry.skipped_faces[k]);
          for (size_t k = 0; k < geometry.faces.size(); ++k) {
            const int file_index = geometry.face_indices.at(k);
            const std::string entity = label + " face " + std::to_string(file_index + 1);
            TrimmedSurface face = geometry.faces[k];
            for (auto& loop : face.loops)
              for (auto& edge : loop.edges)
                if (edge.edge >= 0) edge.edge += out.edge_count;
            try {
              for (const auto& line : repair_trimming_loops(face, entity)) out.warnings.push_back(entity + ": " + line);
            } catch (const GeometryError& e) {
              fall_back(file_index, e.what());
              continue;
            }
            Shape shape;
            shape.source_entity = "face " + std::to_string(file_index + 1);
            shape.source_type = "Brep face";
            shape.geometry = std::move(face);
            node.shapes.push_back(std::move(shape));
            ++out.face_count;
          }
          out.edge_count += geometry.edge_count;
        } else if constexpr (std::is_same_v<T, NurbsSurface>) {
          node.shapes.push_back({"", TrimmedSurface{geometry, {}}, std::nullopt, "NurbsSurface"});
        } else if constexpr (std::is_same_v<T, NurbsCurve>) {
          node.shapes.push_back({"", geometry, std::nullopt, "NurbsCurve"});
        } else if constexpr (std::is_same_v<T, TriangleMesh>) {
          node.shapes.push_back({"", geometry, std::nullopt, "Mesh"});
        } else if constexpr (std::is_same_v<T, RhinoSubd>) {
          out.subd_objects.push_back({node.source_entity, label, geometry.net, geometry.limit_points});
        }
        // Unsupported objects were reported by the file reader and carry nothing.
      },
      object.geometry);
  return node;
}

}  // namespace

RhinoScene scene_from_3dm(const Rhino3dmFile& file, const std::string& root_name) {
  RhinoScene out;
  out.warnings = file.warnings;
  Scene& scene = out.scene;
  scene.root.name = root_name;
  scene.unit = file.unit;
  scene.source_unit = file.unit;

  std::vector<SceneNode> layer_nodes(file.layers.size());
  for (size_t i = 0; i < file.layers.size(); ++i) {
    layer_nodes[i].name = file.layers[i].name;
    layer_nodes[i].source_entity = "layer " + std::to_string(i);
    layer_nodes[i].colour = file.layers[i].colour;
  }
  for (const auto& object : file.objects) {
    if (std::holds_alternative<Unsupported>(object.geometry)) continue;
    SceneNode node = object_node(object, out);
    if (node.shapes.empty() && !std::holds_alternative<RhinoSubd>(object.geometry)) continue;
    const int layer = object.attributes.layer_index;
    if (layer >= 0 && layer < static_cast<int>(layer_nodes.size()))
      layer_nodes[layer].children.push_back(std::move(node));
    else
      scene.root.children.push_back(std::move(node));
  }
  for (auto& layer : layer_nodes)
    if (!layer.children.empty()) scene.root.children.push_back(std::move(layer));

  LengthUnit millimetres;
  scene = in_unit(std::move(scene), millimetres);
  const double scale = file.unit.millimetres / millimetres.millimetres;  // as in_unit scales the scene
  for (auto& subd : out.subd_objects) {
    for (auto& p : subd.net.points) p *= scale;
    for (auto& p : subd.stored_limit_points) p.position *= scale;
  }
  return out;
}

RhinoScene read_3dm(const std::string& path) {
  return scene_from_3dm(read_3dm_file(path), std::filesystem::path(path).stem().string());
}

}  // namespace cadnurbs::rhino
