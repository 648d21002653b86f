# Sources of geometry, discretizer, variation generator, surface type and registration.
