# Installs the build into PREFIX and imports the module from PREFIX/SITE with nothing else on
# the path; fails if the install or the import fails or the module cannot evaluate a law.
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX}
                RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${status})")
endif()
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${PREFIX}/${SITE} ${PYTHON} -c
          "import tribo; assert tribo.__file__.startswith('${PREFIX}'), tribo.__file__; assert tribo.friction_law('coulomb', mu=0.3).mu(2.0) == 0.3"
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the installed module does not import and run (${status})")
endif()
file(REMOVE_RECURSE ${PREFIX})
