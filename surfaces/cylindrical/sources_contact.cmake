# Sources of the contact analyzer and the resistance laws.
#
# They build into a static library (position-independent, hidden visibility) so that the tests
# and benchmarks below use them without the rest of the plugin, and the plugin module links them.
add_library(fitfeel_cylindrical_contact STATIC
  ${CMAKE_CURRENT_LIST_DIR}/cylindrical_assembly_polygon.cc
  ${CMAKE_CURRENT_LIST_DIR}/contact_factory.cc
  ${CMAKE_CURRENT_LIST_DIR}/cylindrical_contact_analyzer.cc
  ${CMAKE_CURRENT_LIST_DIR}/cylindrical_law.cc)
target_link_libraries(fitfeel_cylindrical_contact PUBLIC fitfeel::framework)

# The plugin module is declared in sources_generation.cmake (included first); link this library
# into every module library of this folder so that neither file needs the other's target names.
get_property(_fitfeel_cyl_targets DIRECTORY PROPERTY BUILDSYSTEM_TARGETS)
foreach(_target IN LISTS _fitfeel_cyl_targets)
  get_target_property(_type ${_target} TYPE)
  if(_type STREQUAL "MODULE_LIBRARY")
    target_link_libraries(${_target} PRIVATE fitfeel_cylindrical_contact)
  endif()
endforeach()

# The contact tests build their skin model shapes directly (synthetic V arrays); the geometry
# class's out-of-line members are provided by a test double (test/contact_geometry_double.cc).
fitfeel_add_test(fitfeel_cylindrical_contact_test
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/test/contact_geometry_double.cc
          ${CMAKE_CURRENT_LIST_DIR}/test/contact_polygon_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/test/contact_analyzer_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/test/law_press_fit_test.cc
          ${CMAKE_CURRENT_LIST_DIR}/test/contact_allocation_test.cc
  LIBS fitfeel_cylindrical_contact)

fitfeel_add_benchmark(fitfeel_cylindrical_contact_bench
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/test/contact_geometry_double.cc
          ${CMAKE_CURRENT_LIST_DIR}/bench/contact_benchmark.cc
  LIBS fitfeel_cylindrical_contact)
