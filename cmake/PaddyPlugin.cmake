# paddy_add_plugin(<name> SOURCES <files...> [LIBRARIES <libs...>] [OUTPUT_DIRECTORY <dir>])
# Builds a Paddy plugin: a shared module libpaddy_<name>.so that exports the C entry point
# `paddy_register_plugin` (see docs/plugins.md). Works in Paddy's own tree and out of tree after
# find_package(Paddy). In Paddy's tree the plugin is also installed into lib/paddy/plugins.
function(paddy_add_plugin name)
  cmake_parse_arguments(ARG "" "OUTPUT_DIRECTORY" "SOURCES;LIBRARIES" ${ARGN})
  add_library(paddy_${name} MODULE ${ARG_SOURCES})
  if(TARGET paddy_engine)  # inside Paddy's own build
    target_link_libraries(paddy_${name} PRIVATE paddy_engine paddy_warnings paddy_optimise ${ARG_LIBRARIES})
    set_target_properties(paddy_${name} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${PADDY_PLUGIN_BUILD_DIR})
    install(TARGETS paddy_${name} LIBRARY DESTINATION ${PADDY_PLUGIN_SUBDIR})
  else()                   # out of tree, against an installed Paddy
    target_link_libraries(paddy_${name} PRIVATE Paddy::engine ${ARG_LIBRARIES})
  endif()
  set_target_properties(paddy_${name} PROPERTIES PREFIX "lib" CXX_VISIBILITY_PRESET hidden)
  if(ARG_OUTPUT_DIRECTORY)
    set_target_properties(paddy_${name} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${ARG_OUTPUT_DIRECTORY})
  endif()
endfunction()
