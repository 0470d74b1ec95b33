# Runs choc once and checks its exit code and output (cmake -P, one ctest per call).
#   -DCHOC=path          the choc executable
#   -DARGS=a@@b@@c       its arguments, separated by @@ (may be empty)
#   -DRC=n               expected exit code
#   -DSTDERR_REGEX=re    stderr must match (optional)
#   -DONE_LINE=1         stderr must be exactly one line (the error message)
#   -DSTDOUT_REGEX=r1@@r2 stdout must match every regex (optional)
#   -DWORKDIR=dir        working directory (optional; created when missing)
# Regexes are CMake regexes; they cannot hold ';' (CMake's list separator) nor an unbalanced
# '[' or ']' (no list splitting inside brackets): write '.' there.
cmake_minimum_required(VERSION 3.20)

if(NOT DEFINED CHOC OR NOT DEFINED RC)
  message(FATAL_ERROR "expect.cmake: CHOC and RC are required")
endif()
set(args "")
if(DEFINED ARGS AND NOT ARGS STREQUAL "")
  string(REPLACE "@@" ";" args "${ARGS}")
endif()
if(NOT DEFINED WORKDIR OR WORKDIR STREQUAL "")
  set(WORKDIR "${CMAKE_CURRENT_BINARY_DIR}")
endif()
file(MAKE_DIRECTORY "${WORKDIR}")

execute_process(COMMAND "${CHOC}" ${args}
                WORKING_DIRECTORY "${WORKDIR}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                TIMEOUT 60)

set(failures "")
if(NOT rc STREQUAL "${RC}")
  string(APPEND failures "exit code ${rc}, expected ${RC}\n")
endif()
if(DEFINED STDERR_REGEX AND NOT STDERR_REGEX STREQUAL "")
  if(NOT err MATCHES "${STDERR_REGEX}")
    string(APPEND failures "stderr does not match '${STDERR_REGEX}'\n")
  endif()
endif()
if(ONE_LINE)
  string(REGEX MATCHALL "\n" breaks "${err}")
  list(LENGTH breaks nbreaks)
  if(NOT nbreaks EQUAL 1 OR NOT err MATCHES "\n$")
    string(APPEND failures "stderr is ${nbreaks} line(s), expected exactly one\n")
  endif()
  if(err MATCHES "internal error")
    string(APPEND failures "an internal error, expected an input error\n")
  endif()
endif()
if(DEFINED STDOUT_REGEX AND NOT STDOUT_REGEX STREQUAL "")
  string(REPLACE "@@" ";" outRegexes "${STDOUT_REGEX}")
  foreach(re IN LISTS outRegexes)
    if(NOT out MATCHES "${re}")
      string(APPEND failures "stdout does not match '${re}'\n")
    endif()
  endforeach()
endif()

if(failures)
  string(REPLACE "@@" " " shown "${ARGS}")
  message(FATAL_ERROR "choc ${shown}\n${failures}--- stderr:\n${err}--- stdout (first 2000 chars):\n"
                      "${out}")
endif()
string(REPLACE "@@" " " shown "${ARGS}")
message(STATUS "choc ${shown}: exit ${rc}\n${err}")
