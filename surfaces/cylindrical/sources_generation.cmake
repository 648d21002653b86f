# Sources of geometry, discretizer, variation generator, surface type and registration.
# The skin-model-shape generation is an object library so that its tests link it directly; the
# plugin module (target fitfeel_surface_cylindrical) is declared here, and sources_contact.cmake
# adds the contact analyzer and laws to it with target_sources().
add_library(fitfeel_cylindrical_generation OBJECT
  cylindrical_geometry.cc cylindrical_discretizer.cc cylindrical_generator.cc
  cylindrical_coarse_mesh.cc)
target_link_libraries(fitfeel_cylindrical_generation PUBLIC fitfeel::framework)
fitfeel_add_plugin(fitfeel_surface_cylindrical
  SOURCES cylindrical_surface.cc register.cc $<TARGET_OBJECTS:fitfeel_cylindrical_generation>)
add_subdirectory(test)
