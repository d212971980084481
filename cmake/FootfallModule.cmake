# footfall_module(NAME [SOURCES ...] [DEPENDS ...] [PUBLIC_DIR dir])
#
# One module of the core: the static library footfall_NAME (alias
# footfall::NAME), built from native/src/NAME/. Its public headers
# (native/include/footfall/NAME/, or PUBLIC_DIR) are included as
# "footfall/NAME/x.hpp", its internal ones (native/src/NAME/) as "NAME/x.hpp".
#
# Each module sees only its own headers and those of the modules it DEPENDS
# on, directly or through them: the include roots are staged per module in the
# build tree (links to the source folders), so an include of a module above
# fails to compile instead of quietly tangling the layers.
function(footfall_module name)
  cmake_parse_arguments(MODULE "" "PUBLIC_DIR" "SOURCES;DEPENDS" ${ARGN})
  if(NOT MODULE_PUBLIC_DIR)
    set(MODULE_PUBLIC_DIR ${PROJECT_SOURCE_DIR}/native/include/footfall/${name})
  endif()
  set(internal_dir ${PROJECT_SOURCE_DIR}/native/src/${name})
  set(stage ${CMAKE_BINARY_DIR}/modules/${name})
  file(MAKE_DIRECTORY ${stage}/public/footfall ${stage}/internal)
  set(roots)
  if(EXISTS ${MODULE_PUBLIC_DIR})
    file(CREATE_LINK ${MODULE_PUBLIC_DIR} ${stage}/public/footfall/${name} SYMBOLIC)
    list(APPEND roots ${stage}/public)
  endif()
  if(EXISTS ${internal_dir})
    file(CREATE_LINK ${internal_dir} ${stage}/internal/${name} SYMBOLIC)
    list(APPEND roots ${stage}/internal)
  endif()

  if(MODULE_SOURCES)
    list(TRANSFORM MODULE_SOURCES PREPEND ${CMAKE_CURRENT_SOURCE_DIR}/)
    add_library(footfall_${name} STATIC ${MODULE_SOURCES})
    target_include_directories(footfall_${name} PUBLIC ${roots})
    target_link_libraries(footfall_${name} PUBLIC ${MODULE_DEPENDS})
    target_compile_options(footfall_${name} PRIVATE ${FOOTFALL_WARNINGS})
    set_target_properties(footfall_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  else()
    add_library(footfall_${name} INTERFACE)
    target_include_directories(footfall_${name} INTERFACE ${roots})
    target_link_libraries(footfall_${name} INTERFACE ${MODULE_DEPENDS})
  endif()
  add_library(footfall::${name} ALIAS footfall_${name})
endfunction()
