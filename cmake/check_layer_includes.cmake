cmake_minimum_required(VERSION 3.20)
# cmake -DLAYER=<name> -DALLOWED=<layers> -DFILES=<files> -P check_layer_includes.cmake
# Fails, naming the file, the line and the layers allowed, when a file of LAYER includes a
# header of a layer outside ALLOWED (layers.cmake).
set(refused "")
foreach(file IN LISTS FILES)
  file(STRINGS ${file} includes REGEX "^#include \"sqdem/[a-z_]+/")
  foreach(line IN LISTS includes)
    string(REGEX MATCH "sqdem/([a-z_]+)/" _ "${line}")
    if(NOT CMAKE_MATCH_1 IN_LIST ALLOWED)
      string(APPEND refused "\n  ${file}: ${line}")
    endif()
  endforeach()
endforeach()
if(refused)
  string(REPLACE ";" ", " allowed "${ALLOWED}")
  message(FATAL_ERROR "layer '${LAYER}' includes against the direction of the layers (docs/architecture.md): "
                      "it may include ${allowed}; refused:${refused}")
endif()
