# cmake -DCADNURBS=... -DSAMPLES=... -DCORPUS=... -DOUTPUT=... -P write_cnb_seeds.cmake: the .cnb fuzz
# target's seeds, written by the given cadnurbs into OUTPUT (emptied first): every sample STEP file (trimmed
# NURBS; the moulded capping's weights as two factors), every sample STL (meshes), and the corpus's NURBS
# VRML/X3D files that cadnurbs reads (weights, several surfaces); each sample STEP file once more at
# --deviation 1 (mm), and the corpus's splinecage.stp, whose bodies are written as traversal-coded meshes
# there, io1-tu-203.stp, whose colours are written there as a mesh group, and dm1-id-214.stp, whose meshes
# hold pieces coded as copies there (a mesh group with copies). Fails if one cannot be written.
file(REMOVE_RECURSE ${OUTPUT})
file(MAKE_DIRECTORY ${OUTPUT})
file(GLOB inputs ${SAMPLES}/*.step ${SAMPLES}/*.stl)
list(APPEND inputs ${CORPUS}/vrml/nurbs_weights.x3dv ${CORPUS}/vrml/nurbs_dune_primitives.x3dv
     ${CORPUS}/vrml/NurbsTrimmedSurface.x3d)
foreach(input IN LISTS inputs)
  get_filename_component(name ${input} NAME)
  execute_process(COMMAND ${CADNURBS} convert ${input} -o ${OUTPUT}/${name}.cnb RESULT_VARIABLE status OUTPUT_QUIET)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "write_cnb_seeds: cadnurbs convert ${input} failed (${status})")
  endif()
endforeach()
file(GLOB step_inputs ${SAMPLES}/*.step)
list(APPEND step_inputs ${CORPUS}/step/splinecage.stp ${CORPUS}/step/io1-tu-203.stp ${CORPUS}/step/dm1-id-214.stp)
foreach(input IN LISTS step_inputs)
  get_filename_component(name ${input} NAME)
  execute_process(COMMAND ${CADNURBS} convert ${input} --deviation 1 -o ${OUTPUT}/${name}-coarse.cnb
                  RESULT_VARIABLE status OUTPUT_QUIET)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "write_cnb_seeds: cadnurbs convert ${input} --deviation 1 failed (${status})")
  endif()
endforeach()
