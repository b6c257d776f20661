# Builds the manual: Doxygen XML of the reduced library's headers, then Sphinx HTML.
# Used by the target `doc` and by the test doc.build (STRICT=ON: Sphinx with -W --keep-going and
# a fresh environment, so that every warning of every page is seen and fails the build; Doxygen
# fails on its own warnings through WARN_AS_ERROR in the Doxyfile).
# Variables: SOURCE_DIR (doc/), DOXYFILE (configured), DOXYGEN_XML (its XML folder), OUTPUT
# (HTML folder), DOXYGEN, SPHINX_BUILD (programs; empty when not found), STRICT (ON/OFF).
cmake_minimum_required(VERSION 3.20)
if(NOT DOXYGEN OR NOT SPHINX_BUILD)
  message(FATAL_ERROR "the manual needs doxygen and sphinx-build (found: doxygen '${DOXYGEN}', "
                      "sphinx-build '${SPHINX_BUILD}'): run ./setup.sh (Debian packages doxygen, "
                      "python3-sphinx, python3-myst-parser, python3-sphinx-rtd-theme, "
                      "python3-breathe), then configure again")
endif()
execute_process(COMMAND "${DOXYGEN}" "${DOXYFILE}" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "doxygen failed (${result}) on the reduced library's headers")
endif()
set(options -b html -q)
if(STRICT)
  list(APPEND options -W --keep-going -E)
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env "IMPACT_DOXYGEN_XML=${DOXYGEN_XML}"
                        "${SPHINX_BUILD}" ${options} "${SOURCE_DIR}" "${OUTPUT}"
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "sphinx-build failed (${result}): the warnings above name page and line")
endif()
message(STATUS "manual: ${OUTPUT}/index.html")
