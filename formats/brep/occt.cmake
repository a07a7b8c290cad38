# OpenCASCADE for formats/brep, formats/step, formats/iges and their tests (the only places that may use
# it). Included by each of those folders: CMake's imported targets are visible only below the folder that
# found them.
find_package(OpenCASCADE REQUIRED)

# Debian's OCCT 7.6 export names /usr/lib/.../libtbb.so and libtbbmalloc.so in its link interfaces, but
# those linker names come from libtbb-dev, which the OCCT -dev packages do not pull in. OCCT's own shared
# libraries already depend on the versioned TBB libraries, so an entry naming a missing file is dropped.
foreach(occt_target IN LISTS OpenCASCADE_LIBRARIES)
  if(NOT TARGET ${occt_target})
    continue()
  endif()
  get_target_property(occt_links ${occt_target} INTERFACE_LINK_LIBRARIES)
  if(NOT occt_links)
    continue()
  endif()
  set(occt_kept)
  foreach(occt_link IN LISTS occt_links)
    if(NOT (IS_ABSOLUTE "${occt_link}" AND NOT EXISTS "${occt_link}"))
      list(APPEND occt_kept "${occt_link}")
    endif()
  endforeach()
  set_target_properties(${occt_target} PROPERTIES INTERFACE_LINK_LIBRARIES "${occt_kept}")
endforeach()

# cadnurbs_use_occt(target PRIVATE|PUBLIC toolkit...): OCCT headers as system headers (no warnings from
# them) and the given toolkits. OCC_CONVERT_SIGNALS makes OCC_CATCH_SIGNALS turn a crash inside OCCT
# (e.g. on a damaged file) into a Standard_Failure, as OCCT itself was built.
function(cadnurbs_use_occt target visibility)
  target_include_directories(${target} SYSTEM ${visibility} ${OpenCASCADE_INCLUDE_DIR})
  target_compile_definitions(${target} ${visibility} OCC_CONVERT_SIGNALS)
  target_link_libraries(${target} ${visibility} ${ARGN})
endfunction()
