# OpenCASCADE for formats/brep, formats/step, formats/iges and their tests (the only places that may use
# it). Included by each of those folders: CMake's imported targets are visible only below the folder that
# found them.
find_package(OpenCASCADE REQUIRED)

# Debian's OCCT 7.6 export names libtbb.so in its link interfaces: scripts/setup.sh installs libtbb-dev.

# cadnurbs_use_occt(target PRIVATE|PUBLIC toolkit...): OCCT headers as system headers (no warnings from
# them) and the given toolkits. OCC_CONVERT_SIGNALS makes OCC_CATCH_SIGNALS turn a crash inside OCCT
# (e.g. on a damaged file) into a Standard_Failure, as OCCT itself was built.
function(cadnurbs_use_occt target visibility)
  target_include_directories(${target} SYSTEM ${visibility} ${OpenCASCADE_INCLUDE_DIR})
  target_compile_definitions(${target} ${visibility} OCC_CONVERT_SIGNALS)
  target_link_libraries(${target} ${visibility} ${ARGN})
endfunction()
