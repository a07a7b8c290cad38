# cmake -DCADNURBS=... -DOUTPUT=... [-DPARTS="FILE;..." -DFAMILY=name] [-DLIBRARY=folder] -P write_site.cmake:
# the site `cadnurbs batch --site` writes, of the library folder LIBRARY as it is, or of OUTPUT/lib made of
# copies of PARTS (each with the .stl beside it, if any, as the mesh a library ships) in the folder FAMILY.
# Writes OUTPUT/out (the batch's outputs) and OUTPUT/site; fails when the batch fails for another reason
# than a part (exit status 3 is a failed part, which the site shows).
if(NOT LIBRARY)
  set(LIBRARY ${OUTPUT}/lib)
  file(REMOVE_RECURSE ${OUTPUT})
  foreach(part IN LISTS PARTS)
    file(COPY ${part} DESTINATION ${LIBRARY}/${FAMILY})
    string(REGEX REPLACE "\\.[^.]*$" ".stl" mesh "${part}")
    if(EXISTS ${mesh})
      file(COPY ${mesh} DESTINATION ${LIBRARY}/${FAMILY})
    endif()
  endforeach()
endif()
execute_process(COMMAND ${CADNURBS} batch ${LIBRARY} -o ${OUTPUT}/out --inputs step,iges --jobs 2 --timeout 900
                        --site ${OUTPUT}/site
                RESULT_VARIABLE status)
if(NOT (status EQUAL 0 OR status EQUAL 3))
  message(FATAL_ERROR "write_site: cadnurbs batch ${LIBRARY} --site failed (${status})")
endif()
