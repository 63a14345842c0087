cmake_minimum_required(VERSION 3.20)
# Fails when a source under src/ includes a header of a stage it may not use, or a stage's
# CMake target links one, against the one statement of the rules: the stage table of
# docs/architecture.md ("The stages and their doors"), read here. Its first column names the
# stages (every folder of src/ is one row), its last ("may include") the stages each may use
# besides itself:
#   "—"                                    none;
#   "common, physics, mesh"                those (with or without backticks);
#   "every stage above but `a` and `b/c.hpp`"  every stage of the rows above it, but stage `a`
#                                          and the header `b/c.hpp` (a path: one header refused).
# Checked against it:
#   1. every `#include "<stage>/…"` of src/<stage>/*.?pp (a header refused by its row too);
#   2. every bookspin_<stage> that src/<stage>/CMakeLists.txt links: an allowed stage only;
#   3. every stage a stage includes is linked: by its CMakeLists.txt, or publicly by a stage
#      it links (CMake hands PUBLIC links on).
# And the rules that are not the table's, each stated once here:
#   4. only src/engines links or includes the other engines (the libraries its CMakeLists.txt
#      links besides bookspin's own; their headers by the patterns below);
#   5. bench/ and examples/ sit on top beside the command line: they may not include cli/;
#   6. only src/video links FFmpeg or includes a libav header;
#   7. only src/fit links Ceres or includes a ceres/ header;
#   8. python/, the Python module, is a door beside the command line: its sources include,
#      and its CMakeLists.txt links, only the stages of `python_stages` below: those that make
#      values without files or pictures, and for pictures the clip stage (its frame loop), the
#      products (the clip's files) and the error types of render and video; never cli/ nor
#      cache/, and no drawing of its own (overlay/, charts/).
#   9. only src/typeface calls cairo's own text calls (cairo_show_text, cairo_text_extents,
#      cairo_text_path): every other stage draws text through typeface/text_layout.hpp.
# Run by ctest:
#   cmake -DSOURCE_DIR=<repo> -P tests/architecture/check_includes.cmake
# ARCHITECTURE_DOC=<file> reads the table from another file (to try the check on a changed
# table); the default is SOURCE_DIR/docs/architecture.md.
if(NOT ARCHITECTURE_DOC)
  set(ARCHITECTURE_DOC "${SOURCE_DIR}/docs/architecture.md")
endif()
set(engine_header_regex "^#include <(mujoco/|ode/|bt|Bullet|bullet)")

set(violations "")

# --- The table: stages, in order, and what each may include. ---
file(READ "${ARCHITECTURE_DOC}" doc)
string(REPLACE ";" "," doc "${doc}")  # a CMake list separator inside a cell
string(REPLACE "\n" ";" doc_lines "${doc}")
set(stages "")
set(in_section FALSE)
foreach(line IN LISTS doc_lines)
  if(line MATCHES "^## ")
    set(in_section FALSE)
    if(line MATCHES "^## The stages and their doors")
      set(in_section TRUE)
    endif()
    continue()
  endif()
  if(NOT in_section OR NOT line MATCHES "^\\| `([a-z_]+)` \\|")
    continue()
  endif()
  set(stage "${CMAKE_MATCH_1}")
  if(NOT line MATCHES "\\| ([^|]*[^ |]) *\\|$")
    message(FATAL_ERROR "docs/architecture.md: the row of `${stage}` has no \"may include\" cell")
  endif()
  set(cell "${CMAKE_MATCH_1}")
  set(allowed "${stage}")
  set(refused_headers "")
  if(cell STREQUAL "—")
    # nothing but itself
  elseif(cell MATCHES "^every stage above( but (.*))?$")
    set(exceptions "${CMAKE_MATCH_2}")
    list(APPEND allowed ${stages})
    string(REGEX MATCHALL "`[^`]+`" excepted "${exceptions}")
    foreach(item IN LISTS excepted)
      string(REPLACE "`" "" item "${item}")
      if(item MATCHES "/")
        list(APPEND refused_headers "${item}")
      elseif(item IN_LIST stages)
        list(REMOVE_ITEM allowed "${item}")
      else()
        message(FATAL_ERROR "docs/architecture.md: the row of `${stage}` excepts `${item}`, "
                            "which is no stage above it")
      endif()
    endforeach()
  else()
    string(REPLACE "," ";" items "${cell}")
    foreach(item IN LISTS items)
      string(REPLACE "`" "" item "${item}")
      string(STRIP "${item}" item)
      if(NOT item MATCHES "^[a-z_]+$")
        message(FATAL_ERROR "docs/architecture.md: the row of `${stage}` may include "
                            "\"${item}\", which is not a stage's name")
      endif()
      list(APPEND allowed "${item}")
    endforeach()
  endif()
  if(stage IN_LIST stages)
    message(FATAL_ERROR "docs/architecture.md: the stage `${stage}` has two rows")
  endif()
  list(APPEND stages "${stage}")
  set(allowed_${stage} "${allowed}")
  set(refused_headers_${stage} "${refused_headers}")
endforeach()
if(NOT stages)
  message(FATAL_ERROR "${ARCHITECTURE_DOC}: no stage table under \"## The stages and their doors\"")
endif()
foreach(stage IN LISTS stages)
  foreach(item IN LISTS allowed_${stage})
    if(NOT item IN_LIST stages)
      message(FATAL_ERROR "docs/architecture.md: the row of `${stage}` may include `${item}`, "
                          "which has no row")
    endif()
  endforeach()
endforeach()

# Every folder of src/ is a stage of the table, and every stage a folder.
file(GLOB src_dirs LIST_DIRECTORIES true "${SOURCE_DIR}/src/*")
foreach(dir IN LISTS src_dirs)
  get_filename_component(folder "${dir}" NAME)
  if(IS_DIRECTORY "${dir}" AND NOT folder IN_LIST stages)
    list(APPEND violations "src/${folder}/ has no row in the stage table of docs/architecture.md")
  endif()
endforeach()
foreach(stage IN LISTS stages)
  if(NOT IS_DIRECTORY "${SOURCE_DIR}/src/${stage}")
    list(APPEND violations "the stage table of docs/architecture.md names `${stage}`: no src/${stage}/")
  endif()
endforeach()

# --- 1. Includes. ---
foreach(stage IN LISTS stages)
  set(included_${stage} "")
  file(GLOB files "${SOURCE_DIR}/src/${stage}/*.hpp" "${SOURCE_DIR}/src/${stage}/*.cpp")
  foreach(file IN LISTS files)
    file(RELATIVE_PATH rel "${SOURCE_DIR}" "${file}")
    file(STRINGS "${file}" lines REGEX "^#include \"[a-z_]+/")
    foreach(line IN LISTS lines)
      string(REGEX REPLACE "^#include \"(([a-z_]+)/[^\"]*)\".*" "\\2" included "${line}")
      string(REGEX REPLACE "^#include \"(([a-z_]+)/[^\"]*)\".*" "\\1" header "${line}")
      if(NOT included IN_LIST stages)
        continue()  # generated headers and the like
      endif()
      if(NOT included IN_LIST allowed_${stage})
        list(APPEND violations "${rel}: ${line} (src/${stage} may not include src/${included})")
      elseif(header IN_LIST refused_headers_${stage})
        list(APPEND violations "${rel}: ${line} (src/${stage} may not include ${header})")
      endif()
      if(NOT included STREQUAL stage)
        list(APPEND included_${stage} "${included}")
      endif()
    endforeach()
  endforeach()
  list(REMOVE_DUPLICATES included_${stage})
endforeach()

# --- 2. and 3. Links. ---
foreach(stage IN LISTS stages)
  set(links_${stage} "")
  set(public_links_${stage} "")
  set(external_links_${stage} "")
  set(cmake_file "${SOURCE_DIR}/src/${stage}/CMakeLists.txt")
  if(NOT EXISTS "${cmake_file}")
    continue()
  endif()
  file(READ "${cmake_file}" cmake_text)
  string(REGEX REPLACE "#[^\n]*" "" cmake_text "${cmake_text}")  # comments
  string(REGEX MATCHALL "target_link_libraries\\(bookspin_${stage}[ \t\n][^)]*\\)" calls
               "${cmake_text}")
  foreach(call IN LISTS calls)
    string(REGEX REPLACE "^target_link_libraries\\(bookspin_${stage}[ \t\n]+|\\)$" "" args "${call}")
    string(REGEX REPLACE "[ \t\n]+" ";" args "${args}")
    set(public TRUE)
    foreach(arg IN LISTS args)
      if(arg STREQUAL "PUBLIC" OR arg STREQUAL "INTERFACE")
        set(public TRUE)
      elseif(arg STREQUAL "PRIVATE")
        set(public FALSE)
      elseif(arg MATCHES "^bookspin_([a-z_]+)$" AND CMAKE_MATCH_1 IN_LIST stages)
        set(linked "${CMAKE_MATCH_1}")
        list(APPEND links_${stage} "${linked}")
        if(public)
          list(APPEND public_links_${stage} "${linked}")
        endif()
        if(NOT linked IN_LIST allowed_${stage})
          list(APPEND violations "src/${stage}/CMakeLists.txt links bookspin_${linked} (src/${stage} may not use src/${linked})")
        endif()
      elseif(NOT arg STREQUAL "")
        list(APPEND external_links_${stage} "${arg}")
      endif()
    endforeach()
  endforeach()
endforeach()
foreach(stage IN LISTS stages)
  # What the target sees: its own links, and what those hand on publicly.
  set(reach "${links_${stage}}")
  set(frontier "${links_${stage}}")
  while(frontier)
    list(POP_FRONT frontier next)
    foreach(handed IN LISTS public_links_${next})
      if(NOT handed IN_LIST reach)
        list(APPEND reach "${handed}")
        list(APPEND frontier "${handed}")
      endif()
    endforeach()
  endwhile()
  foreach(included IN LISTS included_${stage})
    if(NOT included IN_LIST reach AND EXISTS "${SOURCE_DIR}/src/${included}/CMakeLists.txt")
      list(APPEND violations "src/${stage} includes src/${included}, but src/${stage}/CMakeLists.txt links neither bookspin_${included} nor a stage that hands it on")
    endif()
  endforeach()
endforeach()

# --- 4. The other engines: src/engines only. ---
set(engine_libraries "")
foreach(library IN LISTS external_links_engines)
  list(APPEND engine_libraries "${library}")
endforeach()
foreach(stage IN LISTS stages)
  if(stage STREQUAL "engines")
    continue()
  endif()
  foreach(library IN LISTS external_links_${stage})
    if(library IN_LIST engine_libraries)
      list(APPEND violations "src/${stage}/CMakeLists.txt links ${library} (only src/engines links the other engines)")
    endif()
  endforeach()
  file(GLOB files "${SOURCE_DIR}/src/${stage}/*.hpp" "${SOURCE_DIR}/src/${stage}/*.cpp")
  foreach(file IN LISTS files)
    file(STRINGS "${file}" lines REGEX "${engine_header_regex}")
    foreach(line IN LISTS lines)
      file(RELATIVE_PATH rel "${SOURCE_DIR}" "${file}")
      list(APPEND violations "${rel}: ${line} (only src/engines includes the other engines)")
    endforeach()
  endforeach()
endforeach()

# --- 5. The bench and the examples may use every stage but the command line. ---
file(GLOB top "${SOURCE_DIR}/bench/*.?pp" "${SOURCE_DIR}/examples/*.cpp")
foreach(file IN LISTS top)
  file(STRINGS "${file}" lines REGEX "^#include \"cli/")
  foreach(line IN LISTS lines)
    file(RELATIVE_PATH rel "${SOURCE_DIR}" "${file}")
    list(APPEND violations "${rel}: ${line} (only the bookspin program uses src/cli)")
  endforeach()
endforeach()

# Every line of a source under src/ but outside src/`stage`/ that matches `pattern`, appended to
# `violations` as "FILE: LINE (why)": what one stage alone may include or call.
function(only_one_stage stage pattern why)
  file(GLOB_RECURSE sources "${SOURCE_DIR}/src/*.hpp" "${SOURCE_DIR}/src/*.cpp")
  foreach(file IN LISTS sources)
    file(RELATIVE_PATH rel "${SOURCE_DIR}" "${file}")
    if(rel MATCHES "^src/${stage}/")
      continue()
    endif()
    file(STRINGS "${file}" lines REGEX "${pattern}")
    foreach(line IN LISTS lines)
      list(APPEND violations "${rel}: ${line} (${why})")
    endforeach()
  endforeach()
  set(violations "${violations}" PARENT_SCOPE)
endfunction()

# --- 6. FFmpeg is the video stage's alone: no other stage links its libraries or includes libav. ---
file(GLOB stage_cmakes "${SOURCE_DIR}/src/*/CMakeLists.txt")
foreach(cmake IN LISTS stage_cmakes)
  file(READ "${cmake}" text)
  file(RELATIVE_PATH rel "${SOURCE_DIR}" "${cmake}")
  if(text MATCHES "PkgConfig::FFMPEG" AND NOT rel STREQUAL "src/video/CMakeLists.txt")
    list(APPEND violations "${rel} links FFmpeg (only src/video does)")
  endif()
endforeach()
only_one_stage(video "^#include <lib(av|sw)" "only src/video includes FFmpeg")

# --- 7. Ceres is the fit stage's alone: no other stage links it or includes a ceres/ header. ---
foreach(cmake IN LISTS stage_cmakes)
  file(READ "${cmake}" text)
  file(RELATIVE_PATH rel "${SOURCE_DIR}" "${cmake}")
  if(text MATCHES "Ceres::" AND NOT rel STREQUAL "src/fit/CMakeLists.txt")
    list(APPEND violations "${rel} links Ceres (only src/fit does)")
  endif()
endforeach()
only_one_stage(fit "^#include <ceres/" "only src/fit includes Ceres")

# --- 9. cairo's own text calls are the typeface stage's alone (its text layout hands them the
# text they draw as before); every other stage's text goes through typeface/text_layout.hpp. ---
only_one_stage(typeface "cairo_(show_text|text_extents|text_path) *\\("
               "only src/typeface calls cairo's text functions: text goes through typeface/text_layout.hpp")

# --- 8. The Python module: the stages that make values, the clip's frames and its product. ---
set(python_stages common physics engines scene mesh analysis fit jobs clip products render video)
list(JOIN python_stages ", " python_stages_text)
file(GLOB python_sources "${SOURCE_DIR}/python/*.hpp" "${SOURCE_DIR}/python/*.cpp")
foreach(file IN LISTS python_sources)
  file(RELATIVE_PATH rel "${SOURCE_DIR}" "${file}")
  file(STRINGS "${file}" lines REGEX "^#include \"[a-z_]+/")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^#include \"([a-z_]+)/.*" "\\1" included "${line}")
    if(included IN_LIST stages AND NOT included IN_LIST python_stages)
      list(APPEND violations "${rel}: ${line} (python/ may use only ${python_stages_text})")
    endif()
  endforeach()
endforeach()
if(EXISTS "${SOURCE_DIR}/python/CMakeLists.txt")
  file(READ "${SOURCE_DIR}/python/CMakeLists.txt" text)
  string(REGEX REPLACE "#[^\n]*" "" text "${text}")
  string(REGEX MATCHALL "bookspin_[a-z_]+" linked "${text}")
  foreach(target IN LISTS linked)
    string(REGEX REPLACE "^bookspin_" "" stage "${target}")
    if(stage IN_LIST stages AND NOT stage IN_LIST python_stages)
      list(APPEND violations "python/CMakeLists.txt links ${target} (python/ may use only ${python_stages_text})")
    endif()
  endforeach()
endif()

list(LENGTH violations count)
if(count GREATER 0)
  list(JOIN violations "\n" text)
  message(FATAL_ERROR "${count} violation(s) of the stage table (docs/architecture.md):\n${text}")
endif()
list(LENGTH stages stage_count)
message(STATUS "every include and link follows the stage table (${stage_count} stages)")
