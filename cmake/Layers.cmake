# The layers of tools/layers.txt (docs/development.md, "Layers"):
# - the target anisomesh_layers runs tools/check_layers.py, which fails the build when a file
#   includes a file of a layer its layer may not use; every layer's target depends on it;
# - every layer under mesher/ becomes the static library anisomesh_<layer>, built from the
#   .cpp files of its folders and linked PUBLIC to the libraries of the layers it uses;
# - ANISOMESH_USES_<layer> holds those libraries for every layer (cad, io, app, cli and
#   python link them where they are defined);
# - anisomesh_mesher is the whole of mesher/ (every mesher layer), for tests and benchmarks.
set(ANISOMESH_LAYER_TABLE ${CMAKE_SOURCE_DIR}/tools/layers.txt)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${ANISOMESH_LAYER_TABLE})
if(NOT Python3_EXECUTABLE)
  find_program(Python3_EXECUTABLE python3 REQUIRED)
endif()

file(STRINGS ${ANISOMESH_LAYER_TABLE} _layer_lines REGEX "^[A-Za-z0-9_]+[ \t]")
set(ANISOMESH_MESHER_LAYERS "")
set(_layer_globs "")
foreach(_line IN LISTS _layer_lines)
  string(FIND "${_line}" ":" _colon)
  if(_colon LESS 0)
    message(FATAL_ERROR "${ANISOMESH_LAYER_TABLE}: no ':' in \"${_line}\"")
  endif()
  string(SUBSTRING "${_line}" 0 ${_colon} _left)
  math(EXPR _after "${_colon} + 1")
  string(SUBSTRING "${_line}" ${_after} -1 _right)
  string(REGEX REPLACE "#.*" "" _right "${_right}")
  separate_arguments(_left UNIX_COMMAND "${_left}")
  separate_arguments(_uses UNIX_COMMAND "${_right}")
  list(POP_FRONT _left _layer)
  set(ANISOMESH_USES_${_layer} "")
  foreach(_use IN LISTS _uses)
    list(APPEND ANISOMESH_USES_${_layer} anisomesh_${_use})
  endforeach()

  set(_sources "")
  set(_in_mesher TRUE)
  foreach(_folder IN LISTS _left)
    list(APPEND _layer_globs ${CMAKE_SOURCE_DIR}/${_folder}/*.h ${CMAKE_SOURCE_DIR}/${_folder}/*.cpp)
    if(NOT _folder MATCHES "^mesher/")
      set(_in_mesher FALSE)
    endif()
    file(GLOB_RECURSE _folder_sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/${_folder}/*.cpp)
    list(APPEND _sources ${_folder_sources})
  endforeach()
  if(_in_mesher)
    if(NOT _sources)
      message(FATAL_ERROR "${ANISOMESH_LAYER_TABLE}: layer ${_layer} has no .cpp file")
    endif()
    add_library(anisomesh_${_layer} STATIC ${_sources})
    target_include_directories(anisomesh_${_layer} PUBLIC ${CMAKE_SOURCE_DIR})
    target_link_libraries(anisomesh_${_layer} PUBLIC ${ANISOMESH_USES_${_layer}})
    add_dependencies(anisomesh_${_layer} anisomesh_layers)
    list(APPEND ANISOMESH_MESHER_LAYERS anisomesh_${_layer})
  endif()
endforeach()

file(GLOB_RECURSE _layered_files CONFIGURE_DEPENDS ${_layer_globs})
add_custom_command(
  OUTPUT ${CMAKE_BINARY_DIR}/layers.stamp
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tools/check_layers.py --root ${CMAKE_SOURCE_DIR}
          --stamp ${CMAKE_BINARY_DIR}/layers.stamp
  DEPENDS ${CMAKE_SOURCE_DIR}/tools/check_layers.py ${ANISOMESH_LAYER_TABLE} ${_layered_files}
  COMMENT "Checking the includes against the layers of tools/layers.txt"
  VERBATIM)
add_custom_target(anisomesh_layers DEPENDS ${CMAKE_BINARY_DIR}/layers.stamp)

add_library(anisomesh_mesher INTERFACE)
target_link_libraries(anisomesh_mesher INTERFACE ${ANISOMESH_MESHER_LAYERS})
