cmake_minimum_required(VERSION 3.20)
# The test-file rule of docs/architecture.md ("Tests"), as it really is:
#   1. every stage (a folder of src/ with sources) has its suite: tests/<stage>/ holding at
#      least one *_test.cpp;
#   2. a test file named after a source, tests/<folder>/<name>_test.cpp where some
#      src/<stage>/<name>.cpp or .hpp exists, sits in that source's stage folder
#      (tests/<stage>/), so that a source moved to another stage takes its test along;
#   3. every other folder of tests/ (catalogues, goldens, the programs' and the browser's
#      tests, ...) is named in docs/architecture.md as `tests/<folder>/`.
# Run by ctest:  cmake -DSOURCE_DIR=<repo> -P tests/architecture/check_test_files.cmake
set(offences "")

file(GLOB src_dirs LIST_DIRECTORIES true "${SOURCE_DIR}/src/*")
set(stages "")
foreach(dir IN LISTS src_dirs)
  file(GLOB sources "${dir}/*.cpp" "${dir}/*.hpp")
  if(IS_DIRECTORY "${dir}" AND sources)
    get_filename_component(stage "${dir}" NAME)
    list(APPEND stages "${stage}")
    file(GLOB tests "${SOURCE_DIR}/tests/${stage}/*_test.cpp")
    if(NOT tests)
      list(APPEND offences "src/${stage}/ has no tests: no tests/${stage}/*_test.cpp")
    endif()
  endif()
endforeach()

file(GLOB test_files "${SOURCE_DIR}/tests/*/*_test.cpp")
foreach(test IN LISTS test_files)
  get_filename_component(name "${test}" NAME)
  string(REGEX REPLACE "_test\\.cpp$" "" name "${name}")
  get_filename_component(folder "${test}" DIRECTORY)
  get_filename_component(folder "${folder}" NAME)
  if(EXISTS "${SOURCE_DIR}/src/${folder}/${name}.cpp" OR EXISTS "${SOURCE_DIR}/src/${folder}/${name}.hpp")
    continue()  # named after a source of its own stage
  endif()
  file(GLOB namesakes "${SOURCE_DIR}/src/*/${name}.cpp" "${SOURCE_DIR}/src/*/${name}.hpp")
  if(namesakes)
    list(GET namesakes 0 namesake)
    file(RELATIVE_PATH namesake "${SOURCE_DIR}" "${namesake}")
    get_filename_component(home "${namesake}" DIRECTORY)
    string(REGEX REPLACE "^src/" "tests/" home "${home}")
    list(APPEND offences
         "tests/${folder}/${name}_test.cpp is named after ${namesake}: it belongs in ${home}/ (or, testing something else, under another name)")
  endif()
endforeach()

file(READ "${SOURCE_DIR}/docs/architecture.md" architecture)
file(GLOB test_dirs LIST_DIRECTORIES true "${SOURCE_DIR}/tests/*")
foreach(dir IN LISTS test_dirs)
  get_filename_component(folder "${dir}" NAME)
  if(NOT IS_DIRECTORY "${dir}" OR folder IN_LIST stages)
    continue()
  endif()
  string(FIND "${architecture}" "`tests/${folder}/`" at)
  if(at EQUAL -1)
    list(APPEND offences "tests/${folder}/ mirrors no stage and docs/architecture.md does not name it (`tests/${folder}/`)")
  endif()
endforeach()

list(LENGTH offences count)
if(count GREATER 0)
  list(JOIN offences "\n" text)
  message(FATAL_ERROR "${count} test file(s) or folder(s) against the test-file rule:\n${text}")
endif()
list(LENGTH stages stage_count)
list(LENGTH test_files test_count)
message(STATUS "the test-file rule holds: ${stage_count} stages with a suite each, ${test_count} test files")
