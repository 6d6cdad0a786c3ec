# Installs the build tree into a private prefix and imports the installed package from there.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "install failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${WORK_DIR}/${PACKAGE_DIR}
                        ${PYTHON} -c "import disklab; assert disklab.__file__.startswith('${WORK_DIR}'); print(disklab.map_names())"
                WORKING_DIRECTORY ${WORK_DIR}  # not the build tree, whose package is on the cwd path
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "importing the installed package failed: ${err}")
endif()
message(STATUS "installed package: ${out}")
