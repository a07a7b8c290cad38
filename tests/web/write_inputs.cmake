# cmake -DCADNURBS=... -DOUTPUT=... -DINPUTS="A;B;..." [-DEXTENSION=html] -P write_inputs.cmake: each input
# written by the given cadnurbs into OUTPUT (emptied first) as NAME.EXTENSION (default cnb) at its default
# deviation (1e-3 of its diagonal), for the browser module's tests. Fails naming the input that cannot be
# written.
if(NOT EXTENSION)
  set(EXTENSION cnb)
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
