# cmake -DCHECK=check_tier_labels.py -DPYTHON=python3 -DLISTING=listing.json -P expect_named.cmake
# Runs the check on a listing with one test made without a tier and one with both: it must exit 1 and
# print exactly these lines.
execute_process(COMMAND ${PYTHON} ${CHECK} --json ${LISTING} RESULT_VARIABLE status OUTPUT_VARIABLE out)
set(expected "made_without_a_tier: no tier label
viewer_both: both tier labels
2 of 3 tests break the rule: each carries exactly one of tier:fast, tier:long
")
if(NOT status EQUAL 1 OR NOT out STREQUAL expected)
  message(FATAL_ERROR "check_tier_labels.py exited ${status} and printed:\n${out}\nexpected exit 1 and:\n${expected}")
endif()
