# The engine's layers (docs/architecture.md, "Layers"): one static library per layer, each
# linking only the layers below it, and a check before each layer compiles that none of its
# files (src/<layer>/, include/sqdem/<layer>/) includes a header of a layer it does not depend
# on, directly or through the layers below: the build refuses an include against the direction.

set(SQDEM_CHECK_INCLUDES ${CMAKE_CURRENT_LIST_DIR}/check_layer_includes.cmake)

# sqdem_layer(<name> SOURCES <files> [DEPENDS <layers>] [LINK <targets>] [PRIVATE <targets>])
function(sqdem_layer name)
  cmake_parse_arguments(PARSE_ARGV 1 layer "" "" "SOURCES;DEPENDS;LINK;PRIVATE")
  # The layers it may include: itself, its dependencies and theirs.
  set(allowed ${name})
  foreach(dependency IN LISTS layer_DEPENDS)
    list(APPEND allowed ${SQDEM_LAYER_${dependency}_ALLOWED})
  endforeach()
  list(REMOVE_DUPLICATES allowed)
  set(SQDEM_LAYER_${name}_ALLOWED ${allowed} PARENT_SCOPE)

  file(GLOB files CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${name}/*.?pp ${PROJECT_SOURCE_DIR}/include/sqdem/${name}/*.hpp)
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/layers/${name}.checked)
  file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/layers)
  add_custom_command(OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} "-DLAYER=${name}" "-DALLOWED=${allowed}" "-DFILES=${files}" -P ${SQDEM_CHECK_INCLUDES}
    COMMAND ${CMAKE_COMMAND} -E touch ${stamp}
    DEPENDS ${files} ${SQDEM_CHECK_INCLUDES}
    COMMENT "Checking the includes of layer ${name}" VERBATIM)
  add_custom_target(sqdem_${name}_includes DEPENDS ${stamp})

  list(TRANSFORM layer_DEPENDS PREPEND sqdem_ OUTPUT_VARIABLE below)
  if(layer_SOURCES)
    add_library(sqdem_${name} STATIC ${layer_SOURCES})
    target_include_directories(sqdem_${name} PUBLIC ${PROJECT_SOURCE_DIR}/include)
    target_link_libraries(sqdem_${name} PUBLIC ${below} ${layer_LINK} PRIVATE ${layer_PRIVATE})
    target_compile_options(sqdem_${name} PRIVATE -Wall -Wextra -Wpedantic)
  else()  # headers only
    add_library(sqdem_${name} INTERFACE)
    target_include_directories(sqdem_${name} INTERFACE ${PROJECT_SOURCE_DIR}/include)
    target_link_libraries(sqdem_${name} INTERFACE ${below} ${layer_LINK})
  endif()
  add_dependencies(sqdem_${name} sqdem_${name}_includes)
endfunction()
