#pragma once
// The body of the VRML/X3D fuzz targets (they differ only in their seeds): the reader must return or
// throw FileError; a file it reads must rewrite as a whole scene graph to each encoding (VRML97, X3D
// classic, X3D XML), and each rewritten text must read again. A throw there is a writer's fault: abort.
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "formats/common/file_io.hpp"
#include "formats/vrml/scene_graph_rewrite.hpp"
#include "formats/vrml/vrml_reader.hpp"

inline void fuzz_vrml_input(const std::string& bytes, const std::string& name) {
  using namespace cadnurbs;
  try {
    (void)parse_vrml(bytes, name);
  } catch (const FileError&) {
    return;
  }
  for (VrmlEncoding encoding : {VrmlEncoding::vrml97, VrmlEncoding::x3d_classic, VrmlEncoding::x3d_xml}) {
    try {
      VrmlWriteOptions options;
      options.encoding = encoding;
      const RewrittenSceneGraph graph = rewrite_scene_graph(bytes, name, options);
      (void)parse_vrml_document(graph.text, name);
    } catch (const std::exception& e) {
      std::cerr << "rewrite to encoding " << static_cast<int>(encoding) << " failed: " << e.what() << "\n";
      std::abort();
    }
  }
}
