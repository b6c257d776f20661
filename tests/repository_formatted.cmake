# The code keeps its style: every C++ file git tracks is as clang-format leaves it, with the
# .clang-format nearest to the file (the top one for reduced/, postprocess/ and tests/, fem's
# own in the deal.II style for fem/). Fails naming the files that differ; the fix is
# `clang-format -i FILE`.
# Variables: SOURCE_DIR (the repository), CLANG_FORMAT (the program).
cmake_minimum_required(VERSION 3.20)
if(NOT CLANG_FORMAT)
  message(FATAL_ERROR "clang-format was not found (setup.sh installs it)")
endif()
execute_process(COMMAND git -C "${SOURCE_DIR}" ls-files "*.cpp" "*.hpp" "*.h" "*.cc"
                RESULT_VARIABLE result OUTPUT_VARIABLE listing ERROR_VARIABLE error)
if(result EQUAL 0)
  string(REGEX REPLACE "\n$" "" listing "${listing}")
  string(REPLACE "\n" ";" files "${listing}")
else() # not a git checkout (an unpacked archive): the sources of the four code folders
  file(GLOB_RECURSE files RELATIVE "${SOURCE_DIR}"
       "${SOURCE_DIR}/fem/*.cc" "${SOURCE_DIR}/fem/*.h" "${SOURCE_DIR}/reduced/*.?pp"
       "${SOURCE_DIR}/postprocess/*.?pp" "${SOURCE_DIR}/tests/*.?pp")
endif()
set(unformatted "")
foreach(file IN LISTS files)
  execute_process(COMMAND "${CLANG_FORMAT}" --dry-run -Werror "${file}"
                  WORKING_DIRECTORY "${SOURCE_DIR}" RESULT_VARIABLE result
                  OUTPUT_QUIET ERROR_QUIET)
  if(NOT result EQUAL 0)
    list(APPEND unformatted "${file}")
  endif()
endforeach()
list(LENGTH files checked)
if(unformatted)
  list(JOIN unformatted "\n  " text)
  message(FATAL_ERROR "not as clang-format leaves them (run clang-format -i):\n  ${text}")
endif()
message(STATUS "${checked} C++ files as clang-format leaves them")
