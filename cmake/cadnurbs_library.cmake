# cadnurbs_library(NAME SOURCES FILE... [DEPENDS TARGET...] [PRIVATE TARGET...])
# The static library cadnurbs_NAME of one concept folder: its sources; DEPENDS, the libraries its headers
# use (linked PUBLIC); PRIVATE, those only its sources use. A folder may include the headers of the
# libraries it declares and of none other (dependencies point inward, DESIGN.md's layout).
# With the tests on, also link_check_NAME: an executable that holds every object of the library (whole
# archive) and links the declared libraries only, so that a call into an undeclared library fails the
# build there, whatever else the final executables link.
function(cadnurbs_library name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "SOURCES;DEPENDS;PRIVATE")
  if(arg_UNPARSED_ARGUMENTS OR NOT arg_SOURCES)
    message(FATAL_ERROR "cadnurbs_library(${name}): SOURCES FILE... [DEPENDS ...] [PRIVATE ...]")
  endif()
  add_library(cadnurbs_${name} STATIC ${arg_SOURCES})
  target_include_directories(cadnurbs_${name} PUBLIC ${CADNURBS_SOURCE_DIR})
  target_link_libraries(cadnurbs_${name} PUBLIC ${arg_DEPENDS} PRIVATE ${arg_PRIVATE})
  if(CADNURBS_TESTS)
    add_executable(link_check_${name} ${CADNURBS_SOURCE_DIR}/tests/layering/link_check_main.cpp)
    target_link_libraries(link_check_${name} PRIVATE "$<LINK_LIBRARY:WHOLE_ARCHIVE,cadnurbs_${name}>")
    set_target_properties(link_check_${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/link_checks)
  endif()
endfunction()
