# Test tiers (tests/README.md): every ctest test carries exactly one of the labels tier:fast (`make test`,
# what CI runs) and tier:long (`make test-long`); the test tiers.every_test_has_one_tier fails, naming
# them, on tests that carry neither or both.

# cadnurbs_discover_tests(TARGET PREFIX [LONG PATTERN...] [EXCEPT PATTERN...] [PROPERTIES NAME VALUE...])
# gtest_discover_tests for TARGET, its cases named PREFIX<Suite>.<Case>: the cases matching a LONG
# pattern (gtest filter syntax: SubdivisionFitAgainstQuadric.*, Corpus/*/step_11752_stp) labelled tier:long
# unless they also match an EXCEPT pattern (a long family's fast smoke case), all the others tier:fast.
# PROPERTIES go to every case (a LABELS among them would replace the tier: don't).
function(cadnurbs_discover_tests target prefix)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "LONG;EXCEPT;PROPERTIES")
  if(arg_UNPARSED_ARGUMENTS OR (arg_EXCEPT AND NOT arg_LONG))
    message(FATAL_ERROR "cadnurbs_discover_tests(${target}): unexpected ${arg_UNPARSED_ARGUMENTS}")
  endif()
  set(common ${target} TEST_PREFIX ${prefix} DISCOVERY_TIMEOUT 60)
  if(arg_LONG)
    list(JOIN arg_LONG ":" long)
    set(except "")
    if(arg_EXCEPT)
      list(JOIN arg_EXCEPT ":" except)
      gtest_discover_tests(${common} TEST_FILTER "${except}" PROPERTIES LABELS tier:fast ${arg_PROPERTIES})
    endif()
    gtest_discover_tests(${common} TEST_FILTER "-${long}" PROPERTIES LABELS tier:fast ${arg_PROPERTIES})
    gtest_discover_tests(${common} TEST_FILTER "${long}-${except}" PROPERTIES LABELS tier:long ${arg_PROPERTIES})
  else()
    gtest_discover_tests(${common} PROPERTIES LABELS tier:fast ${arg_PROPERTIES})
  endif()
endfunction()

# cadnurbs_test_tier(fast|long TEST...): adds the tier's label to tests registered with add_test (their
# other labels, such as viewer, stay).
function(cadnurbs_test_tier tier)
  if(NOT tier MATCHES "^(fast|long)$")
    message(FATAL_ERROR "cadnurbs_test_tier: the tier is fast or long, not '${tier}'")
  endif()
  foreach(test IN LISTS ARGN)
    set_property(TEST ${test} APPEND PROPERTY LABELS tier:${tier})
  endforeach()
endfunction()
