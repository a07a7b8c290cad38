# Script mode (cmake -P): writes OUTPUT from TEMPLATE with the text of INPUT as a raw string literal.
# INPUT may be empty (the library is missing): the text is then empty.
if(INPUT AND EXISTS "${INPUT}")
  file(READ "${INPUT}" EMBED_TEXT)
  set(EMBED_SOURCE "${INPUT}")
else()
  set(EMBED_TEXT "")
  set(EMBED_SOURCE "nothing (the PROTO library was missing)")
endif()
string(FIND "${EMBED_TEXT}" ")cadnurbs_protos\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw string delimiter )cadnurbs_protos\"")
endif()
configure_file("${TEMPLATE}" "${OUTPUT}" @ONLY)
