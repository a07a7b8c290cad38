# cmake -DCADNURBS=... -DOUTPUT=... -DINPUTS="A;B;..." [-DLIBRARY_PARTS="Family/Part;..." -DFETCH=script]
#       [-DEXTENSION=html] -P write_inputs.cmake: each input, and each part of the part library (its STEP
# file in the folder FETCH, scripts/fetch-part-library.sh, prints), written by the given cadnurbs into
# OUTPUT (emptied first) as NAME.EXTENSION (default cnb) at its default deviation (1e-3 of its diagonal),
# for the browser module's tests. Fails naming the input that cannot be written.
if(NOT EXTENSION)
  set(EXTENSION cnb)
endif()
if(LIBRARY_PARTS)
  execute_process(COMMAND bash ${FETCH} OUTPUT_VARIABLE library OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "write_inputs: ${FETCH} failed (${status})")
  endif()
  foreach(part IN LISTS LIBRARY_PARTS)
    string(REGEX REPLACE "/.*" "" family "${part}")
    string(REGEX REPLACE "^[^/]*/" "" name "${part}")
    list(APPEND INPUTS ${library}/${family}.3dshapes/${name}.step)
  endforeach()
endif()
file(REMOVE_RECURSE ${OUTPUT})
file(MAKE_DIRECTORY ${OUTPUT})
foreach(input IN LISTS INPUTS)
  get_filename_component(name ${input} NAME)
  execute_process(COMMAND ${CADNURBS} convert ${input} -o ${OUTPUT}/${name}.${EXTENSION} RESULT_VARIABLE status OUTPUT_QUIET)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "write_inputs: cadnurbs convert ${input} failed (${status})")
  endif()
endforeach()
