# Installed with the package (find_package(fitfeel) includes it).
set(_FITFEEL_PLUGIN_EXPORTS ${CMAKE_CURRENT_LIST_DIR}/plugin_exports.map)

# fitfeel_add_plugin_module(<name> SOURCES ... [LIBS ...]) builds a surface or device plugin
# outside fitfeel's tree exactly as the tree builds its own: a loadable module lib<name>.so
# linking fitfeel::fitfeel, C++20, hidden visibility, and only the registration hook exported
# (the version script). FITFEEL_REGISTER_SURFACE / FITFEEL_REGISTER_DEVICE
# (framework/plugin/plugin_entry.h) write the hook and its ABI handshake. Put the module in a
# folder named by FITFEEL_PLUGIN_PATH for `fitfeel` and the registry to find it.
function(fitfeel_add_plugin_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  add_library(${name} MODULE ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE fitfeel::fitfeel ${ARG_LIBS})
  set_target_properties(${name} PROPERTIES
    PREFIX "lib"
    CXX_STANDARD 20
    CXX_STANDARD_REQUIRED ON
    CXX_EXTENSIONS OFF
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  target_link_options(${name} PRIVATE -Wl,--version-script=${_FITFEEL_PLUGIN_EXPORTS})
  set_property(TARGET ${name} APPEND PROPERTY LINK_DEPENDS ${_FITFEEL_PLUGIN_EXPORTS})
endfunction()
