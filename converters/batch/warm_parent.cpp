#include "converters/batch/warm_parent.hpp"

#include <unistd.h>

#include <filesystem>

#include "converters/file_formats.hpp"

namespace cadnurbs {

namespace {

// A unit square, one bilinear face.
Scene square_part() {
  NurbsSurface s;
  s.u_order = s.v_order = 2;
  s.u_count = s.v_count = 2;
  s.u_knots = s.v_knots = {0, 0, 1, 1};
  s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  Scene scene;
  scene.root.name = "warm";
  scene.root.shapes.push_back({"square", TrimmedSurface{s, {}}, std::nullopt});
  return scene;
}

}  // namespace

void warm_up_readers() {
  namespace fs = std::filesystem;
  std::error_code ignored;
  const fs::path folder = fs::temp_directory_path(ignored) / ("cadnurbs-warm-" + std::to_string(::getpid()));
  try {
    fs::create_directories(folder);
    const Scene part = square_part();
    for (const char* name : {"warm.step", "warm.iges"}) {
      const std::string path = (folder / name).string();
      write_scene(path, part, SceneWriteOptions{});
      load_scene(path);  // in this process: the wall's child would take the warmth with it
    }
  } catch (const std::exception&) {
  }
  fs::remove_all(folder, ignored);
}

}  // namespace cadnurbs
